using System.Reflection;
using NSubstitute;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// The synchronous calls (<see cref="HostLinkSynchronousExtensions"/>) that timer-driven legacy code makes: they give
/// the value on a UI thread stand-in without deadlocking, throw the library's own exceptions (never an
/// <see cref="AggregateException"/>), and run the asynchronous path itself — same validation, deadlines and retries.
/// </summary>
public sealed class SynchronousCallTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(60);

    /// <summary>One call per synchronous method, in an order the simulator accepts (bits through a FINS view).</summary>
    private static IEnumerable<(string Method, Action<HostLinkClient, IHostLinkUnit> Call)> Calls() =>
    [
        ("WriteWords", (c, _) => c.WriteWords("D100", 1, 2, 3)),
        ("WriteWord", (c, _) => c.WriteWord("D103", 4)),
        ("ReadWords", (c, _) => c.ReadWords("D100", 4).Should().Equal(1, 2, 3, 4)),
        ("ReadWord", (c, _) => c.ReadWord("D103").Should().Be(4)),
        ("Write", (c, _) => c.Write("D200", 2.5f)),
        ("Write", (c, _) => c.Write("D210", new[] { -1, 7 })),
        ("Read", (c, _) => c.Read<float>("D200").Should().Be(2.5f)),
        ("Read", (c, _) => c.Read<int>("D210", 2).Should().Equal(-1, 7)),
        ("WriteBcd", (c, _) => c.WriteBcd("D220", 1234)),
        ("ReadBcd", (c, _) => c.ReadBcd("D220").Should().Be(1234)),
        ("WriteString", (c, _) => c.WriteString("D230", "LOT42")),
        ("ReadString", (c, _) => c.ReadString("D230", 5).Should().Be("LOT42")),
        ("WriteBit", (_, f) => f.WriteBit("W400.07", true)),
        ("ReadBit", (_, f) => f.ReadBit("W400.07").Should().BeTrue()),
        ("ReadBit", (c, _) => c.ReadBit("D100.00").Should().BeTrue()),
        ("ReadTags", (c, _) => c.ReadTags("D100", "D200:float").Select(v => v.Value).Should().Equal(new object[] { (ushort)1, 2.5f })),
        ("ReadStatus", (c, _) => c.ReadStatus().Mode.Should().Be(PlcMode.Program)),
        ("SetMode", (c, _) => c.SetMode(PlcMode.Monitor)),
        ("ReadErrors", (c, _) => c.ReadErrors().Should().NotBeNull()),
        ("ReadModel", (c, _) => c.ReadModel().Should().NotBeNull()),
        ("Test", (c, _) => c.Test().Should().BePositive()),
    ];

    [Fact]
    public void Every_synchronous_method_is_covered_here()
    {
        HashSet<string> covered = Calls().Select(c => c.Method).ToHashSet();
        typeof(HostLinkSynchronousExtensions).GetMethods(BindingFlags.Public | BindingFlags.Static)
            .Select(m => m.Name).Distinct().Where(n => !covered.Contains(n))
            .Should().BeEmpty("every synchronous method is called here from the UI thread stand-in");
    }

    [Fact]
    public async Task Every_synchronous_method_gives_its_value_on_a_UI_thread_without_deadlock()
    {
        await using InProcessLine line = InProcessLine.Start();
        IHostLinkUnit fins = line.Client.Unit(0, HostLinkCommandSet.Fins);
        using var ui = new SingleThreadContext();
        var done = new List<string>();

        await ui.Run(
            () =>
            {
                foreach ((string method, Action<HostLinkClient, IHostLinkUnit> call) in Calls())
                {
                    call(line.Client, fins);
                    done.Add(method);
                }
            },
            Limit);

        done.Should().HaveCount(Calls().Count());
        line.Plc.Mode.Should().Be(PlcMode.Monitor);
        line.Plc.GetBit("W400.07").Should().BeTrue();
    }

    [Fact]
    public async Task Failures_are_the_library_exceptions_themselves()
    {
        await using InProcessLine line = InProcessLine.Start(
            new HostLinkClientOptions { TurnaroundAllowance = TimeSpan.FromMilliseconds(300), ReadRetries = 0 },
            new OmronHostLink.Simulator.VirtualPlcOptions { InitialMode = PlcMode.Run });
        using var ui = new SingleThreadContext();
        Exception? refused = null;
        Exception? silent = null;
        Exception? badAddress = null;
        Exception? cModeBit = null;

        await ui.Run(
            () =>
            {
                refused = Record.Exception(() => line.Client.WriteWord("D0", 1));
                silent = Record.Exception(() => line.Client.Unit(9).ReadWords("D0", 1));
                badAddress = Record.Exception(() => line.Client.ReadWords("Q12", 1));
                cModeBit = Record.Exception(() => line.Client.WriteBit("W400.07", true));
            },
            Limit);

        refused.Should().BeOfType<HostLinkEndCodeException>("C-mode writes are refused in RUN mode (end code 01)")
            .Which.EndCode.Should().Be(EndCode.NotExecutableInRunMode);
        silent.Should().BeOfType<HostLinkTimeoutException>("unit 09 is not on the line");
        badAddress.Should().BeOfType<FormatException>();
        cModeBit.Should().BeOfType<ArgumentException>().Which.Message.Should().Contain("HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins");
    }

    [Fact]
    public async Task A_synchronous_read_has_the_same_retries_as_the_asynchronous_one()
    {
        await using InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { TurnaroundAllowance = TimeSpan.FromMilliseconds(200), ReadRetries = 2 });
        IHostLinkUnit silent = line.Client.Unit(7);

        // The first failure leaves the link out of step; from then on every call starts with the same fence.
        await FluentActions.Awaiting(() => silent.ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();
        int before = line.FramesSent;
        await FluentActions.Awaiting(() => silent.ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();
        int asyncFrames = line.FramesSent - before;
        before = line.FramesSent;
        FluentActions.Invoking(() => silent.ReadWords("D0", 1)).Should().Throw<HostLinkTimeoutException>()
            .Which.Message.Should().Contain("3 attempts");
        int syncFrames = line.FramesSent - before;

        syncFrames.Should().Be(asyncFrames, "the same path: three attempts and the same resynchronisation around them");
    }

    [Fact]
    public void The_synchronous_calls_run_the_asynchronous_methods_of_any_IHostLinkUnit()
    {
        IHostLinkUnit plc = Substitute.For<IHostLinkUnit>();
        plc.ReadWordsAsync("D100", 2, Arg.Any<CancellationToken>()).Returns(Task.FromResult(new ushort[] { 7, 8 }));
        plc.ReadAsync<Bcd16>("D5", Arg.Any<CancellationToken>()).Returns(Task.FromResult(new Bcd16(42)));
        plc.ReadStatusAsync(Arg.Any<CancellationToken>()).Returns(Task.FromException<PlcStatus>(new HostLinkTimeoutException("silent", TimeSpan.FromSeconds(1))));

        plc.ReadWords("D100", 2).Should().Equal(7, 8);
        plc.ReadBcd("D5").Should().Be(42);
        plc.WriteBit("CIO 1.02", true);
        FluentActions.Invoking(() => plc.ReadStatus()).Should().Throw<HostLinkTimeoutException>();

        plc.Received(1).ReadWordsAsync("D100", 2, Arg.Any<CancellationToken>());
        plc.Received(1).WriteBitAsync("CIO 1.02", true, Arg.Any<CancellationToken>());
    }
}
