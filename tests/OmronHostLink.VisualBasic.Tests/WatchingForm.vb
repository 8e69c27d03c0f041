''' <summary>
''' A form that holds a HostLinkPlc as it held the OCX, as docs/migrating.md shows it; the handlers are the guide's code.
''' Label stand-ins record every text they are given in Changes, for the tests to wait on.
''' </summary>
Public NotInheritable Class WatchingForm
    Implements IDisposable

    Friend ReadOnly Changes As New System.Collections.Concurrent.BlockingCollection(Of String)()
    Friend WithEvents HostLinkPlc1 As New HostLinkPlc()
    Friend ReadOnly Label1 As New Label(Changes)
    Friend ReadOnly Label2 As New Label(Changes)

    Public Sub StartWatching(portName As String)
        HostLinkPlc1.PortName = portName                       ' or Host and TcpPort for a serial-device server
        HostLinkPlc1.Tags = {"D100", "D200:float", "CIO 10.03"}
        HostLinkPlc1.Interval = 500                            ' milliseconds, as a Timer's
        HostLinkPlc1.Start()                                   ' the handlers run on this (the UI) thread
    End Sub

    Private Sub HostLinkPlc1_ValueChanged(sender As Object, e As TagValueChangedEventArgs) Handles HostLinkPlc1.ValueChanged
        Label1.Text = $"{e.TagText} = {e.NewValue}"
    End Sub

    Private Sub HostLinkPlc1_ConnectionLost(sender As Object, e As ConnectionLostEventArgs) Handles HostLinkPlc1.ConnectionLost
        Label2.Text = "PLC not answering: " & e.Exception.Message
    End Sub

    Private Sub HostLinkPlc1_ConnectionRestored(sender As Object, e As ConnectionRestoredEventArgs) Handles HostLinkPlc1.ConnectionRestored
        Label2.Text = "OK"
    End Sub

    Private Sub HostLinkPlc1_Error(sender As Object, e As WatchErrorEventArgs) Handles HostLinkPlc1.Error
        Label2.Text = "A handler failed: " & e.Exception.Message
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        HostLinkPlc1.Dispose()                                 ' the form's components do this when it closes
        Changes.Dispose()
    End Sub
End Class
