Imports System.Net
Imports OmronHostLink
Imports OmronHostLink.Simulator
Imports OmronHostLink.Simulator.Hosting

' Reads and writes registers with blocking calls in a Using block, as timer-driven VB.NET code does.
'   dotnet run --project samples/OmronHostLink.VisualBasic.Sample                 the simulator on 127.0.0.1
'   dotnet run --project samples/OmronHostLink.VisualBasic.Sample -- 192.0.2.10:4001 a serial-device server
'   dotnet run --project samples/OmronHostLink.VisualBasic.Sample -- COM3          a serial port
Module Program
    Function Main(args As String()) As Integer
        Dim simulator As TcpSimulatorHost = Nothing
        Dim target As String
        If args.Length = 0 Then
            Dim plc As New VirtualPlc()
            plc.WriteWords("D100", New UShort() {1234, &H42})
            simulator = New TcpSimulatorHost(plc, New IPEndPoint(IPAddress.Loopback, 0))
            simulator.StartAsync().GetAwaiter().GetResult()
            target = $"127.0.0.1:{simulator.EndPoint.Port}"
            Console.WriteLine($"Simulated PLC on {target}")
        Else
            target = args(0)
        End If

        Try
            Using plc = Open(target)
                Poll(plc)
            End Using
            Return 0
        Catch ex As HostLinkException
            Console.Error.WriteLine(ex.Message)
            Return 4
        Finally
            simulator?.StopAsync().GetAwaiter().GetResult()
        End Try
    End Function

    Private Function Open(target As String) As HostLinkClient
        Dim colon = target.LastIndexOf(":"c)
        Dim port As Integer
        If colon > 0 AndAlso Integer.TryParse(target.Substring(colon + 1), port) Then
            Return HostLinkClient.ForTcp(target.Substring(0, colon), port)
        End If
        Return HostLinkClient.ForSerialPort(target)
    End Function

    ' What a Timer.Tick handler does: read, show, write back; three ticks here.
    Private Sub Poll(plc As HostLinkClient)
        Dim status = plc.ReadStatus()
        Console.WriteLine($"Unit {plc.UnitNumber:D2} is in {status.Mode} mode.")
        For tick = 1 To 3
            Dim words As UShort() = plc.ReadWords("D100", 2)
            Dim counter As Integer = plc.ReadBcd("D101")
            Console.WriteLine($"Tick {tick}: D100 = {words(0)}, D101 (BCD) = {counter}")
            Try
                plc.WriteBcd("D101", (counter + 1) Mod 10000)
            Catch ex As HostLinkEndCodeException When ex.EndCode = EndCode.NotExecutableInRunMode
                Console.WriteLine("The PLC is in RUN mode: switch it to MONITOR to write.")
            End Try
            Threading.Thread.Sleep(100)
        Next
    End Sub
End Module
