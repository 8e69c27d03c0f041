using System.Diagnostics;
using System.Text;
using OmronHostLink.Capture;
using OmronHostLink.Cli.LineMonitoring;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// The monitor's pipeline without ports: chunks of a line's bytes in any fragmentation, cut into frames and paired into
/// exchanges. Frames are golden vectors; times are Stopwatch ticks the test chooses.
/// </summary>
public sealed class LineMonitorTests
{
    private static readonly long Ms = Stopwatch.Frequency / 1000;

    /// <summary>RD of DM 0000, 1 word, to unit 00, and its answer (golden vectors).</summary>
    private const string ReadCommand = "@00RD0000001057*\r";

    private const string ReadAnswer = "@00RD00000AFFFF80002F*\r";

    [Fact]
    public void A_command_and_its_answer_are_paired_with_the_latency_from_the_commands_last_byte_to_the_answers_first()
    {
        List<MonitorEvent> events = Run(
            (0, "@00RD0000001057*\r", 10),
            (0, "@00RD00000AFFFF80002F*\r", 13));

        MonitoredExchange x = Single(events);
        x.Unit.Should().Be(0);
        x.Header.Should().Be("RD");
        x.Status.Should().Be(ExchangeStatus.Ok);
        x.EndCode.Should().Be("00");
        x.Latency.Should().Be(TimeSpan.FromMilliseconds(3));
        x.CommandFrames.Should().ContainSingle().Which.Direction.Should().Be(LineDirection.ToPlc);
        x.AnswerFrames.Should().ContainSingle().Which.Direction.Should().Be(LineDirection.FromPlc);
    }

    [Fact]
    public void A_divided_answer_is_one_exchange_with_the_hosts_cr_between_its_frames()
    {
        string[] answer = GoldenFrames.Rd40Frames;

        List<MonitorEvent> events = Run(
            (0, "@00RD0000004052*\r", 10),
            (0, answer[0], 20),
            (0, "\r", 21),
            (0, answer[1], 25));

        MonitoredExchange x = Single(events);
        x.Status.Should().Be(ExchangeStatus.Ok);
        x.CommandFrames.Select(f => f.Text).Should().Equal(@"@00RD0000004052*\r", @"\r");
        x.AnswerFrames.Should().HaveCount(2);
        x.AnswerFrames.Should().OnlyContain(f => f.Direction == LineDirection.FromPlc);
    }

    [Fact]
    public void A_divided_command_is_one_exchange_with_the_plcs_cr_between_its_frames()
    {
        string[] command = GoldenFrames.Wd50Frames;

        List<MonitorEvent> events = Run(
            (0, command[0], 10),
            (0, "\r", 11),
            (0, command[1], 20),
            (0, "@00WD0053*\r", 22));

        MonitoredExchange x = Single(events);
        x.Header.Should().Be("WD");
        x.Status.Should().Be(ExchangeStatus.Ok);
        x.CommandFrames.Should().HaveCount(2);
        x.AnswerFrames.Select(f => f.Text).Should().Equal(@"\r", @"@00WD0053*\r");
        x.Latency.Should().Be(TimeSpan.FromMilliseconds(2), "from the command's last frame to the answer");
    }

    [Fact]
    public void A_command_nobody_answers_is_reported_when_the_next_one_comes()
    {
        List<MonitorEvent> events = Run(
            (0, "@05MS5B*\r", 10),
            (0, "@00RD0000001057*\r", 400),
            (0, "@00RD00000AFFFF80002F*\r", 403));

        List<MonitoredExchange> exchanges = events.OfType<MonitorEvent.Exchanged>().Select(e => e.Exchange).ToList();
        exchanges.Select(x => (x.Unit, x.Header, x.Status)).Should().Equal((5, "MS", ExchangeStatus.Unanswered), (0, "RD", ExchangeStatus.Ok));
        exchanges[0].Latency.Should().BeNull();
    }

    [Fact]
    public void An_error_end_code_and_a_damaged_answer_are_told_apart()
    {
        List<MonitorEvent> events = Run(
            (0, "@00WD0010000250*\r", 10),
            (0, "@00WD0152*\r", 12),
            (0, "@00RD0000001057*\r", 20),
            (0, "@00RD00000AFFFF80002E*\r", 23));

        List<MonitoredExchange> exchanges = events.OfType<MonitorEvent.Exchanged>().Select(e => e.Exchange).ToList();
        exchanges[0].Status.Should().Be(ExchangeStatus.EndCode);
        exchanges[0].EndCode.Should().Be("01");
        exchanges[1].Status.Should().Be(ExchangeStatus.Damaged);
        exchanges[1].Problems.Should().ContainSingle().Which.Should().Contain("FCS error");
    }

    [Fact]
    public void A_ts_echo_and_a_fins_answer_are_answers()
    {
        List<MonitorEvent> events = Run(
            (0, "@00TS==HelloPLC5A*\r", 10),
            (0, "@00TS==HelloPLC5A*\r", 11),
            (0, "@00FA00000000001018200640000027D*\r", 20),
            (0, "@00FA0040000000010100001234ABCD43*\r", 22));

        List<MonitoredExchange> exchanges = events.OfType<MonitorEvent.Exchanged>().Select(e => e.Exchange).ToList();
        exchanges.Select(x => (x.Header, x.Status, x.EndCodeText)).Should().Equal(("TS", ExchangeStatus.Ok, "--"), ("FA", ExchangeStatus.Ok, "00/0000"));
    }

    [Fact]
    public void Frames_cut_across_chunks_keep_the_times_of_their_first_and_last_bytes()
    {
        var events = new List<MonitorEvent>();
        var monitor = new LineMonitor(twoPorts: false, new MonitorClock(), null, events.Add);

        monitor.Take(Chunk(0, "\x01\x02@00RD00", 10));
        monitor.Take(Chunk(0, "00001057*\r@00RD00", 12));
        monitor.Take(Chunk(0, "000AFFFF80002F*\r", 14));
        monitor.Flush(20 * Ms);

        events.OfType<MonitorEvent.Noise>().Should().ContainSingle().Which.Frame.Bytes.Should().Equal(1, 2);
        MonitoredExchange x = Single(events);
        x.CommandFrames[0].FirstTicks.Should().Be(10 * Ms);
        x.CommandFrames[0].LastTicks.Should().Be(12 * Ms);
        x.Latency.Should().Be(TimeSpan.Zero, "the answer's first byte came in the chunk that ended the command");
    }

    [Fact]
    public void With_two_ports_frames_are_put_back_in_line_order_before_pairing()
    {
        var events = new List<MonitorEvent>();
        var monitor = new LineMonitor(twoPorts: true, new MonitorClock(), null, events.Add);

        // The PLC's reader handed its answer over before the host's reader handed over the command.
        monitor.Take(Chunk(1, "@00RD00000AFFFF80002F*\r", 13));
        monitor.Take(Chunk(0, "@00RD0000001057*\r", 10));
        monitor.Flush(100 * Ms);

        MonitoredExchange x = Single(events);
        x.Status.Should().Be(ExchangeStatus.Ok);
        x.Latency.Should().Be(TimeSpan.FromMilliseconds(3));
    }

    [Fact]
    public void With_two_ports_a_reader_that_runs_late_does_not_put_its_answers_after_the_next_command()
    {
        var events = new List<MonitorEvent>();
        LineMonitor monitor = TwoPortsAfterACommand(events);
        monitor.Take(Chunk(0, ReadCommand, 200));
        monitor.Held.Should().Be(1, "the second command waits for the PLC's reader to read past it");
        events.Should().BeEmpty();

        // The PLC's reader wakes 250 ms late and reads both answers at once: stamped after the second command, but its
        // watermark says they may have come any time after 5 ms.
        monitor.Take(Chunk(1, ReadAnswer + ReadAnswer, 260, clearMs: 259));
        monitor.Flush(300 * Ms);

        events.Should().AllBeOfType<MonitorEvent.Exchanged>();
        events.OfType<MonitorEvent.Exchanged>().Select(e => e.Exchange)
            .Select(x => (x.Status, x.CommandFrames.Count, x.AnswerFrames.Count))
            .Should().Equal((ExchangeStatus.Ok, 1, 1), (ExchangeStatus.Ok, 1, 1));
    }

    [Fact]
    public void With_two_ports_a_command_nobody_answered_is_closed_when_the_plc_reader_has_read_past_the_next_one()
    {
        var events = new List<MonitorEvent>();
        LineMonitor monitor = TwoPortsAfterACommand(events);
        monitor.Take(Chunk(0, ReadCommand, 100));
        monitor.Take(Quiet(1, 60));
        events.Should().BeEmpty("the PLC's reader has not yet read past the second command");

        monitor.Take(Quiet(1, 101));
        Single(events).Status.Should().Be(ExchangeStatus.Unanswered);

        monitor.Take(Chunk(1, ReadAnswer, 110));
        monitor.Flush(200 * Ms);
        List<MonitoredExchange> exchanges = events.OfType<MonitorEvent.Exchanged>().Select(e => e.Exchange).ToList();
        exchanges.Select(x => x.Status).Should().Equal(ExchangeStatus.Unanswered, ExchangeStatus.Ok);
        exchanges[1].Latency.Should().Be(TimeSpan.FromMilliseconds(10));
    }

    [Fact]
    public void With_two_ports_an_answer_nobody_asked_for_waits_for_the_host_reader_then_is_a_stray()
    {
        var events = new List<MonitorEvent>();
        var monitor = new LineMonitor(twoPorts: true, new MonitorClock(), null, events.Add);

        monitor.Take(Chunk(1, ReadAnswer, 10));
        events.Should().BeEmpty("the host's reader may still hold the command it answers");

        monitor.Take(Quiet(0, 11));
        events.Should().ContainSingle().Which.Should().BeOfType<MonitorEvent.Stray>();
    }

    /// <summary>Two ports: the PLC's port found quiet at 5 ms, then the host's RD at 10 ms (paired at once: nothing came before it).</summary>
    private static LineMonitor TwoPortsAfterACommand(List<MonitorEvent> events)
    {
        var monitor = new LineMonitor(twoPorts: true, new MonitorClock(), null, events.Add);
        monitor.Take(Quiet(1, 5));
        monitor.Take(Chunk(0, ReadCommand, 10));
        return monitor;
    }

    private static MonitoredExchange Single(List<MonitorEvent> events)
        => events.OfType<MonitorEvent.Exchanged>().Should().ContainSingle().Which.Exchange;

    private static List<MonitorEvent> Run(params (int Source, string Frame, int AtMs)[] frames)
    {
        var events = new List<MonitorEvent>();
        var monitor = new LineMonitor(twoPorts: false, new MonitorClock(), null, events.Add);
        foreach ((int source, string frame, int at) in frames)
        {
            monitor.Take(Chunk(source, frame, at));
        }

        monitor.Flush(100_000 * Ms);
        return events;
    }

    /// <summary>A read that returned <paramref name="text"/> at <paramref name="atMs"/>, having begun at <paramref name="clearMs"/> (by default just before).</summary>
    private static TapChunk Chunk(int source, string text, int atMs, int? clearMs = null)
        => new(source, Encoding.Latin1.GetBytes(text), atMs * Ms, (clearMs ?? atMs - 1) * Ms);

    /// <summary>A poll that began at <paramref name="atMs"/> and found the port quiet.</summary>
    private static TapChunk Quiet(int source, int atMs) => new(source, [], atMs * Ms, atMs * Ms);
}
