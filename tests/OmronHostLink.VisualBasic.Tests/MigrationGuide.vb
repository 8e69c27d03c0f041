' The code of docs/migrating.md: each of its blocks is copied from this file (a test checks they match), and the
' tests in MigrationGuideTests run these against the simulator.

''' <summary>Opening the link: the settings a copied class or an OCX held, in one place.</summary>
Public Module Connections
    Public Function OpenSerial(portName As String) As HostLinkClient
        Dim line As New SerialLineSettings With {
            .PortName = portName,
            .BaudRate = 9600,
            .DataBits = 7,
            .Parity = SerialParity.Even,
            .StopBits = SerialStopBits.Two
        }
        Dim options As New HostLinkClientOptions With {
            .UnitNumber = 0,
            .TurnaroundAllowance = TimeSpan.FromMilliseconds(300)
        }
        Return HostLinkClient.ForSerialPort(line, options)
    End Function

    Public Function OpenTcp(host As String, port As Integer) As HostLinkClient
        Dim options As New HostLinkClientOptions With {
            .LineTiming = New LineTiming(9600, 11)
        }
        Return HostLinkClient.ForTcp(host, port, options)
    End Function
End Module

''' <summary>The calls a copied Host Link class or an OCX made, in this library's terms.</summary>
Public Module Registers
    Public Function ReadAndWriteDm(plc As IHostLinkUnit) As String
        Dim count As UShort = plc.ReadWord("D100")             ' binary word
        Dim setpoint As Integer = plc.ReadBcd("D101")          ' BCD word: &H1234 reads as 1234
        Dim block As UShort() = plc.ReadWords("D200", 10)      ' ten words, one command
        plc.WriteWord("D300", count)
        plc.WriteBcd("D301", setpoint + 1)                     ' 1235 is written as &H1235
        plc.WriteWords("D310", 1, 2, 3)
        Dim speed As Single = plc.Read(Of Single)("D400")      ' REAL: two words, low word first
        Dim total As Integer = plc.Read(Of Integer)("D402")    ' DINT: two words
        Dim recipe As String = plc.ReadString("D500", 8)       ' ASCII, two characters a word
        Return $"{count} {setpoint} {block.Length} {speed} {total} {recipe}"
    End Function

    Public Function Bits(plc As HostLinkClient) As Boolean
        Dim running As Boolean = plc.ReadBit("CIO 10.03")
        Dim fins = plc.Unit(0, HostLinkCommandSet.Fins)        ' C-mode has no bit write: FINS writes one bit
        fins.WriteBit("W400.07", True)                         ' the work area is FINS only, reads too
        fins.WriteBit("CIO 100.00", Not running)
        Dim done As Boolean = plc.ReadBit("T5")                ' timer 5's completion flag
        Return fins.ReadBit("W400.07") AndAlso done
    End Function

    Public Function ModeAndStatus(plc As IHostLinkUnit) As String
        Dim status As PlcStatus = plc.ReadStatus()
        If status.Mode = PlcMode.Run Then
            plc.SetMode(PlcMode.Monitor)                       ' C-mode writes are refused in RUN mode
        End If
        Dim errors As PlcErrorInfo = plc.ReadErrors()
        Dim model As PlcModel = plc.ReadModel()
        Dim roundTrip As TimeSpan = plc.Test()
        Return $"{status.Mode} {errors} {model} {roundTrip > TimeSpan.Zero}"
    End Function

    Public Function WriteCarefully(plc As IHostLinkUnit) As String
        Try
            plc.WriteWord("D100", 1)
            Return "written"
        Catch ex As HostLinkEndCodeException When ex.EndCode = EndCode.NotExecutableInRunMode
            Return "the PLC is in RUN mode: switch it to MONITOR to write"
        Catch ex As HostLinkTimeoutException
            Return "no answer: check the cable, the unit number and the port settings"
        Catch ex As HostLinkException When ex.IsTransient
            Return "the line had a problem; the next try may work"
        End Try
    End Function
End Module
