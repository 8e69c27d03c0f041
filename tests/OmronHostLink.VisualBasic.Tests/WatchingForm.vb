''' <summary>
''' A form that holds a HostLinkPlc as it held the OCX, as docs/migrating.md shows it; the handlers are the guide's code.
''' </summary>
Public NotInheritable Class WatchingForm
    Implements IDisposable

    Friend WithEvents HostLinkPlc1 As New HostLinkPlc()
    Friend ReadOnly Label1 As New Label()
    Friend ReadOnly Label2 As New Label()
    Friend ReadOnly Changes As New System.Collections.Concurrent.BlockingCollection(Of String)()

    Private Sub HostLinkPlc1_ValueChanged(sender As Object, e As TagValueChangedEventArgs) Handles HostLinkPlc1.ValueChanged
        Label1.Text = $"{e.TagText} = {e.NewValue}"
        Changes.Add(Label1.Text)
    End Sub

    Private Sub HostLinkPlc1_ConnectionLost(sender As Object, e As ConnectionLostEventArgs) Handles HostLinkPlc1.ConnectionLost
        Label2.Text = "PLC not answering: " & e.Exception.Message
        Changes.Add(Label2.Text)
    End Sub

    Private Sub HostLinkPlc1_ConnectionRestored(sender As Object, e As ConnectionRestoredEventArgs) Handles HostLinkPlc1.ConnectionRestored
        Label2.Text = "OK"
        Changes.Add(Label2.Text)
    End Sub

    Private Sub HostLinkPlc1_Error(sender As Object, e As WatchErrorEventArgs) Handles HostLinkPlc1.Error
        Label2.Text = "A handler failed: " & e.Exception.Message
        Changes.Add(Label2.Text)
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        HostLinkPlc1.Dispose()
        Changes.Dispose()
    End Sub
End Class
