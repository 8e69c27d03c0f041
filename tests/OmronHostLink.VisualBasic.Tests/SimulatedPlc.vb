Imports System.Net
Imports OmronHostLink.Simulator
Imports OmronHostLink.Simulator.Hosting

''' <summary>The simulator on a TCP loopback port, as a serial-device server would be; Dispose stops it.</summary>
Public NotInheritable Class SimulatedPlc
    Implements IDisposable

    Private _host As TcpSimulatorHost

    Public Sub New(Optional options As VirtualPlcOptions = Nothing)
        Plc = New VirtualPlc(options)
        _host = New TcpSimulatorHost(Plc, New IPEndPoint(IPAddress.Loopback, 0))
        _host.StartAsync().GetAwaiter().GetResult()
        Port = _host.EndPoint.Port
    End Sub

    Public ReadOnly Property Plc As VirtualPlc

    Public ReadOnly Property Port As Integer

    Public ReadOnly Property ActiveSessions As Integer
        Get
            Return _host.ActiveSessions
        End Get
    End Property

    ''' <summary>Options for a client of the simulator: it answers at once, so the allowance only has to catch a lost answer.</summary>
    Public Shared Function ClientOptions() As HostLinkClientOptions
        Return New HostLinkClientOptions With {
            .LineTiming = New LineTiming(115200, 11),
            .TurnaroundAllowance = TimeSpan.FromSeconds(5)
        }
    End Function

    ''' <summary>The serial-device server goes away: its connections close and nothing listens on the port.</summary>
    Public Sub GoAway()
        _host.StopAsync().GetAwaiter().GetResult()
    End Sub

    ''' <summary>The server comes back on the same port, with the same PLC memory.</summary>
    Public Sub ComeBack()
        _host = New TcpSimulatorHost(Plc, New IPEndPoint(IPAddress.Loopback, Port))
        _host.StartAsync().GetAwaiter().GetResult()
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        _host.StopAsync().GetAwaiter().GetResult()
    End Sub
End Class
