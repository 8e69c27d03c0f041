Imports System.Threading
Imports OmronHostLink.Simulator

''' <summary>The code of docs/migrating.md, run against the simulator.</summary>
Public Class MigrationGuideTests
    Private Shared ReadOnly Limit As TimeSpan = TimeSpan.FromSeconds(30)

    <Fact>
    Public Sub The_DM_calls_read_and_write_binary_BCD_REAL_DINT_and_text()
        Using sim As New SimulatedPlc()
            sim.Plc.WriteWords("D100", New UShort() {42, &H1234})
            sim.Plc.WriteWords("D500", New UShort() {&H4142, &H4344})
            Using plc = Connections.OpenTcp("127.0.0.1", sim.Port)
                Dim summary = Registers.ReadAndWriteDm(plc)

                Assert.Equal("42 1234 10 0 0 ABCD", summary)
                Assert.Equal(New UShort() {42, &H1235}, sim.Plc.ReadWords("D300", 2))
                Assert.Equal(New UShort() {1, 2, 3}, sim.Plc.ReadWords("D310", 3))
            End Using
        End Using
    End Sub

    <Fact>
    Public Sub The_bit_calls_write_through_FINS_and_read_back()
        Using sim As New SimulatedPlc()
            sim.Plc.SetBit("CIO10.03", True)
            sim.Plc.SetFlag(PlcArea.Timer, 5, True)
            Using plc = HostLinkClient.ForTcp("127.0.0.1", sim.Port, SimulatedPlc.ClientOptions())
                Assert.True(Registers.Bits(plc))
                Assert.True(sim.Plc.GetBit("W400.07"))
                Assert.False(sim.Plc.GetBit("CIO100.00"))
            End Using
        End Using
    End Sub

    <Fact>
    Public Sub The_mode_calls_switch_RUN_to_MONITOR()
        Using sim As New SimulatedPlc(New VirtualPlcOptions With {.InitialMode = PlcMode.Run})
            Using plc = HostLinkClient.ForTcp("127.0.0.1", sim.Port, SimulatedPlc.ClientOptions())
                Assert.StartsWith("Run ", Registers.ModeAndStatus(plc))
                Assert.Equal(PlcMode.Monitor, sim.Plc.Mode)
                Assert.Equal("written", Registers.WriteCarefully(plc))
            End Using
        End Using
    End Sub

    <Fact>
    Public Sub The_component_raises_its_events_on_the_UI_thread_and_a_failing_handler_goes_to_Error()
        Using sim As New SimulatedPlc(), ui As New UiThread(), form As New WatchingForm()
            sim.Plc.WriteWords("D100", New UShort() {5})
            form.HostLinkPlc1.Host = "127.0.0.1"
            form.HostLinkPlc1.TcpPort = sim.Port
            form.HostLinkPlc1.BaudRate = 115200
            form.HostLinkPlc1.TurnaroundAllowance = TimeSpan.FromSeconds(5)
            form.HostLinkPlc1.Tags = {"D100", "D200:bcd"}
            form.HostLinkPlc1.Interval = 20

            ui.Run(Sub() form.HostLinkPlc1.Start(), Limit)

            Assert.Equal("D100 = 0x0005", Take(form.Changes))
            Assert.Equal("D200:bcd = 0", Take(form.Changes))
            Assert.Equal(ui.ThreadId, form.Label1.TextThreadId)

            ' Not BCD: the cycle fails, and the watch says so once, then again when the value is good.
            sim.Plc.WriteWords("D200", New UShort() {&HA1})
            Assert.StartsWith("PLC not answering: ", Take(form.Changes))
            sim.Plc.WriteWords("D200", New UShort() {&H12})
            Assert.Equal("OK", Take(form.Changes))
            Assert.Equal("D200:bcd = 12", Take(form.Changes))

            ' A handler that throws: the Error event says so and the watch goes on.
            AddHandler form.HostLinkPlc1.ValueChanged, AddressOf ThrowingHandler
            sim.Plc.WriteWords("D100", New UShort() {6})
            Assert.Equal("D100 = 0x0006", Take(form.Changes))
            Assert.Equal("A handler failed: a bug in a handler", Take(form.Changes))
            sim.Plc.WriteWords("D100", New UShort() {7})
            Assert.Equal("D100 = 0x0007", Take(form.Changes))
            Assert.Empty(ui.ThreadExceptions)
        End Using
    End Sub

    <Fact>
    Public Sub Blocking_reads_through_the_component_client_share_the_link_with_its_watch()
        Using sim As New SimulatedPlc(), ui As New UiThread(), form As New WatchingForm()
            form.HostLinkPlc1.Host = "127.0.0.1"
            form.HostLinkPlc1.TcpPort = sim.Port
            form.HostLinkPlc1.TurnaroundAllowance = TimeSpan.FromSeconds(5)
            form.HostLinkPlc1.Tags = {"D100"}
            form.HostLinkPlc1.Interval = 20
            ui.Run(Sub() form.HostLinkPlc1.Start(), Limit)
            Take(form.Changes)

            ui.Run(Sub() form.HostLinkPlc1.Client.WriteWord("D100", 99), Limit)

            Assert.Equal("D100 = 0x0063", Take(form.Changes))
            form.Dispose()
            Assert.True(SpinWait.SpinUntil(Function() sim.ActiveSessions = 0, Limit), "disposing the form's component closed the socket")
        End Using
    End Sub

    <Fact>
    Public Sub A_port_that_cannot_be_opened_is_ConnectionLost_on_the_UI_thread()
        Using ui As New UiThread(), form As New WatchingForm()
            ui.Run(Sub() form.StartWatching("/tmp/omronhostlink-no-such-port"), Limit)

            Dim lost = Take(form.Changes)
            Assert.StartsWith("PLC not answering: ", lost)
            Assert.Contains("/tmp/omronhostlink-no-such-port", lost)
            Assert.Equal(ui.ThreadId, form.Label2.TextThreadId)
            Assert.True(form.HostLinkPlc1.IsWatching, "the watch keeps trying")
        End Using
    End Sub

    Private Shared Sub ThrowingHandler(sender As Object, e As TagValueChangedEventArgs)
        Throw New InvalidOperationException("a bug in a handler")
    End Sub

    Private Shared Function Take(changes As System.Collections.Concurrent.BlockingCollection(Of String)) As String
        Dim item As String = Nothing
        Assert.True(changes.TryTake(item, Limit), "an event came in time")
        Return item
    End Function
End Class
