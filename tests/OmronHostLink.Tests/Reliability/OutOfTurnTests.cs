using System.Globalization;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;
using OmronHostLink.Simulator.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Testing;
using Xunit.Abstractions;

namespace OmronHostLink.Tests.Reliability;

/// <summary>
/// Reads of several addresses with the same shape (RD of 4 words at D0, D1000, D2000, D3000, in turn) on an emulated
/// 9600 bps line that delivers answers out of turn (held back a second while later commands are answered, then sent
/// between them) and drops answers. A C-mode answer carries no address, so a late answer to one read has the shape of
/// any later one; each address holds words no other address holds, so a value taken from another read is seen.
/// </summary>
[Trait("Category", "Slow")]
public sealed class OutOfTurnTests(ITestOutputHelper output)
{
    private static readonly string[] Addresses = ["D0", "D1000", "D2000", "D3000"];

    private static int Reads => int.TryParse(Environment.GetEnvironmentVariable("HOSTLINK_OUT_OF_TURN_READS"), NumberStyles.Integer, CultureInfo.InvariantCulture, out int n) && n > 0 ? n : 400;

    private static int Seed => int.TryParse(Environment.GetEnvironmentVariable("HOSTLINK_OUT_OF_TURN_SEED"), NumberStyles.Integer, CultureInfo.InvariantCulture, out int n) ? n : 20261127;

    [Fact]
    public async Task Answers_out_of_turn_are_never_taken_for_a_later_read_by_default_verified_or_in_FINS()
    {
        var faults = new FaultOptions { OutOfTurn = 0.05, Drop = 0.05, LateBy = TimeSpan.FromSeconds(1) };
        Run[] runs = await Task.WhenAll(
            RunAsync("C-mode", faults, o => { }, reads: 2 * Reads),
            RunAsync("C-mode, VerifyAnswers", faults, o => o.VerifyAnswers = true),
            RunAsync("FINS", faults, o => o.CommandSet = HostLinkCommandSet.Fins));

        foreach (Run run in runs)
        {
            output.WriteLine(run.ToString());
            output.WriteLine(run.Debug.ToString());
        }

        Run plain = runs[0];
        plain.Faults.OutOfTurn.Should().BeGreaterThan(0, "answers were delivered out of turn");
        // What C-mode cannot see by default (docs/reliability.md): a late answer in the right one's time while the right one
        // is lost on the line. Measured 0 of 800 on a quiet machine and 3 of 800 under load.
        plain.Wrong.Should().BeLessThanOrEqualTo(plain.Reads / 100, "at most 1 % of C-mode reads by default");
        plain.WrongInARow.Should().Be(0, "never two in a row");
        runs[1].Wrong.Should().Be(0, "with VerifyAnswers");
        runs[2].Wrong.Should().Be(0, "FINS answers carry their command's service ID");
        runs.Should().OnlyContain(r => r.Untyped == 0);
    }

    [Fact]
    public async Task A_slow_PLC_that_answers_in_order_after_every_deadline_gives_typed_timeouts_and_no_value()
    {
        var faults = new FaultOptions { Late = 1, LateBy = TimeSpan.FromMilliseconds(400) };
        Run run = await RunAsync("C-mode, every answer late in order", faults, o => { }, reads: 12);
        output.WriteLine(run.ToString());
        run.Wrong.Should().Be(0);
        run.Good.Should().Be(0);
        run.Timeouts.Should().Be(run.Reads);
    }

    private static async Task<Run> RunAsync(string name, FaultOptions faults, Action<HostLinkClientOptions> configure, int? reads = null)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions
        {
            BaudRate = 9600,
            Turnaround = TimeSpan.FromMilliseconds(5),
            Faults = new FaultOptions
            {
                Seed = Seed,
                Drop = faults.Drop,
                OutOfTurn = faults.OutOfTurn,
                Late = faults.Late,
                LateBy = faults.LateBy,
            },
        });
        for (int a = 0; a < Addresses.Length; a++)
        {
            plc.WriteWords(Addresses[a], Expected(a));
        }

        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = plc.RunAsync(plcEnd, stop.Token);
        var logs = new CapturingLoggerProvider();
        using var factory = Microsoft.Extensions.Logging.LoggerFactory.Create(b => b.SetMinimumLevel(Microsoft.Extensions.Logging.LogLevel.Trace).AddProvider(logs));
        var options = new HostLinkClientOptions { LineTiming = new OmronHostLink.Transports.LineTiming(9600, 11), LoggerFactory = factory };
        configure(options);
        var run = new Run(name);
        await using (HostLinkClient client = HostLinkClient.ForStream(host, options))
        {
            bool lastWrong = false;
            for (int i = 0; i < (reads ?? Reads); i++)
            {
                int a = i % Addresses.Length;
                run.Reads++;
                try
                {
                    ushort[] words = await client.ReadWordsAsync(Addresses[a], 4);
                    bool wrong = !words.AsSpan().SequenceEqual(Expected(a));
                    run.Good += wrong ? 0 : 1;
                    run.Wrong += wrong ? 1 : 0;
                    if (wrong)
                    {
                        run.Debug.AppendLine($"WRONG read {i} {Addresses[a]}: {string.Join(",", words.Select(w => w.ToString("X4")))}");
                        foreach (var e in logs.Entries.TakeLast(30)) run.Debug.AppendLine($"  {e.Time:HH:mm:ss.fff} {e.EventId.Id} {e.Message}");
                    }

                    run.WrongInARow += wrong && lastWrong ? 1 : 0;
                    lastWrong = wrong;
                }
                catch (HostLinkTimeoutException)
                {
                    run.Timeouts++;
                    lastWrong = false;
                }
                catch (HostLinkException)
                {
                    run.OtherFailures++;
                    lastWrong = false;
                }
                catch (Exception)
                {
                    run.Untyped++;
                    lastWrong = false;
                }
            }
        }

        stop.Cancel();
        await session;
        run.Faults = plc.FaultCounters;
        return run;
    }

    /// <summary>Words only address <paramref name="a"/> holds.</summary>
    private static ushort[] Expected(int a) => [(ushort)(0x1000 * (a + 1)), (ushort)((0x1000 * (a + 1)) + 1), (ushort)((0x1000 * (a + 1)) + 2), (ushort)((0x1000 * (a + 1)) + 3)];

    private sealed class Run(string name)
    {
        public int Reads { get; set; }

        public int Good { get; set; }

        public int Wrong { get; set; }

        public int WrongInARow { get; set; }

        public int Timeouts { get; set; }

        public int OtherFailures { get; set; }

        public int Untyped { get; set; }

        public FaultCounters Faults { get; set; } = new();

        public System.Text.StringBuilder Debug { get; } = new();

        public override string ToString()
            => $"{name}: {Reads} reads, {Good} right, {Wrong} wrong ({100.0 * Wrong / Math.Max(1, Reads):0.00} %), {WrongInARow} wrong right after a wrong one, {Timeouts} timeouts, {OtherFailures} other typed failures, {Untyped} untyped; simulator {Faults}";
    }
}
