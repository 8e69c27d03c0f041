Imports System.Threading
Imports OmronHostLink.Simulator

''' <summary>Using, blocking calls from a timer tick on the UI thread, and Try/Catch on the library's exceptions.</summary>
Public Class UsingAndBlockingTests
    Private Shared ReadOnly Limit As TimeSpan = TimeSpan.FromSeconds(30)

    <Fact>
    Public Sub A_Using_block_reads_and_writes_and_closes_the_socket_at_End_Using()
        Using sim As New SimulatedPlc()
            Dim client As HostLinkClient
            Using plc = HostLinkClient.ForTcp("127.0.0.1", sim.Port, SimulatedPlc.ClientOptions())
                client = plc
                plc.WriteWords("D100", 10, 20, 30)
                Assert.Equal(New UShort() {10, 20, 30}, plc.ReadWords("D100", 3))
                Assert.Equal(1, sim.ActiveSessions)
            End Using

            Assert.True(SpinWait.SpinUntil(Function() sim.ActiveSessions = 0, Limit), "End Using closed the socket")
            Assert.Throws(Of ObjectDisposedException)(Sub() client.ReadWord("D100"))
        End Using
    End Sub

    <Fact>
    Public Sub Blocking_calls_from_a_timer_tick_on_the_UI_thread_update_the_labels_and_survive_an_outage()
        Using sim As New SimulatedPlc(), ui As New UiThread()
            sim.Plc.WriteWords("D100", New UShort() {7, 8})
            Using plc = HostLinkClient.ForTcp("127.0.0.1", sim.Port, SimulatedPlc.ClientOptions())
                Dim form As New PollingForm(plc)

                form.Timer1.PerformTick(ui)
                Assert.Equal("7 / 8", form.Label1.Text)
                Assert.Equal("OK", form.Label2.Text)
                Assert.Equal(ui.ThreadId, form.Label1.TextThreadId)

                sim.Plc.WriteWords("D101", New UShort() {9})
                form.Timer1.PerformTick(ui)
                Assert.Equal("7 / 9", form.Label1.Text)

                ' The server goes away: the tick catches the library's exception, and the next tick after it is back reads again.
                sim.GoAway()
                form.Timer1.PerformTick(ui)
                Assert.NotEqual("OK", form.Label2.Text)
                sim.ComeBack()
                form.Timer1.PerformTick(ui)
                Assert.Equal("OK", form.Label2.Text)
                Assert.Equal("7 / 9", form.Label1.Text)
            End Using
            Assert.Empty(ui.ThreadExceptions)
        End Using
    End Sub

    <Fact>
    Public Sub Result_and_Wait_on_the_UI_thread_neither_deadlock_nor_hide_the_library_exception()
        Using sim As New SimulatedPlc(New VirtualPlcOptions With {.InitialMode = PlcMode.Run}), ui As New UiThread()
            Using plc = HostLinkClient.ForTcp("127.0.0.1", sim.Port, SimulatedPlc.ClientOptions())
                Dim words As UShort() = Nothing
                Dim wrapped As AggregateException = Nothing
                Dim direct As HostLinkEndCodeException = Nothing
                ui.Run(Sub()
                           words = plc.ReadWordsAsync("D0", 2).Result
                           Try
                               plc.WriteWordAsync("D0", 1).Wait()
                           Catch ex As AggregateException
                               wrapped = ex
                           End Try
                           Try
                               plc.WriteWord("D0", 1)
                           Catch ex As HostLinkEndCodeException
                               direct = ex
                           End Try
                       End Sub, Limit)

                Assert.Equal(2, words.Length)
                Assert.IsType(Of HostLinkEndCodeException)(wrapped.InnerException)
                Assert.Equal(EndCode.NotExecutableInRunMode, direct.EndCode)
            End Using
        End Using
    End Sub

    <Fact>
    Public Sub Try_Catch_on_the_typed_exceptions()
        Using sim As New SimulatedPlc(New VirtualPlcOptions With {.InitialMode = PlcMode.Run})
            Dim options As New HostLinkClientOptions With {.LineTiming = New LineTiming(115200, 11), .TurnaroundAllowance = TimeSpan.FromMilliseconds(300), .ReadRetries = 0}
            Using plc = HostLinkClient.ForTcp("127.0.0.1", sim.Port, options)
                Assert.Equal("the PLC is in RUN mode: switch it to MONITOR to write", Registers.WriteCarefully(plc))
                Assert.Equal("no answer: check the cable, the unit number and the port settings", Registers.WriteCarefully(plc.Unit(9)))

                Dim refused As String = Nothing
                Try
                    plc.WriteBit("W400.07", True)
                Catch ex As ArgumentException
                    refused = ex.Message
                End Try
                Assert.Contains("HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins", refused)
                Assert.Contains("plc.Unit(0, HostLinkCommandSet.Fins)", refused)

                Try
                    plc.ReadWords("D1O0", 1)
                    Assert.Fail("a bad address is refused")
                Catch ex As FormatException
                    Assert.Contains("D1O0", ex.Message)
                End Try

                plc.SetMode(PlcMode.Monitor)
                Assert.Equal("written", Registers.WriteCarefully(plc))
            End Using
        End Using
    End Sub
End Class
