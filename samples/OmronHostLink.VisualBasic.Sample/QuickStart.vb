Imports OmronHostLink

' The README's VB.NET quick start, word for word (a test checks it): a serial port on this machine.
Public Module QuickStart
    Public Sub Run()
        Using plc = HostLinkClient.ForSerialPort("COM3")                ' 9600 7E2, unit 00 (Omron defaults)
            Dim dm As UShort() = plc.ReadWords("D100", 30)              ' blocking: fine from a Timer.Tick
            Dim temperature As Single = plc.Read(Of Single)("D200")     ' REAL: two words, low word first
            Dim setpoint As Integer = plc.ReadBcd("D210")               ' a BCD word: &H1234 reads as 1234
            plc.WriteWords("D300", 1, 2, 3)                             ' done only when the PLC answers 00
            Dim running As Boolean = plc.ReadBit("CIO 100.05")
            Try
                plc.WriteWord("D400", CUShort(setpoint))
            Catch ex As HostLinkEndCodeException When ex.EndCode = EndCode.NotExecutableInRunMode
                plc.SetMode(PlcMode.Monitor)                            ' C-mode writes need MONITOR mode
            End Try
            Console.WriteLine($"{dm(0)} {temperature} {running}")
        End Using
    End Sub
End Module
