''' <summary>
''' A form as docs/migrating.md shows it: a Timer whose Tick reads with blocking calls. Timer and Label are stand-ins
''' for WinForms' (see FormStandIns.vb); the handler is the guide's code.
''' </summary>
Public NotInheritable Class PollingForm
    Friend WithEvents Timer1 As New Timer()
    Friend ReadOnly Label1 As New Label()
    Friend ReadOnly Label2 As New Label()
    Private ReadOnly plc As HostLinkClient

    Public Sub New(client As HostLinkClient)
        plc = client
    End Sub

    Private Sub Timer1_Tick(sender As Object, e As EventArgs) Handles Timer1.Tick
        Try
            Dim words As UShort() = plc.ReadWords("D100", 2)
            Label1.Text = $"{words(0)} / {words(1)}"
            Label2.Text = "OK"
        Catch ex As HostLinkException
            Label2.Text = ex.Message                           ' the next tick tries again
        End Try
    End Sub
End Class
