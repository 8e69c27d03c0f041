using System.Collections.Concurrent;
using System.Net;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// <see cref="HostLinkWatcher"/> and <see cref="HostLinkPlc"/>: <c>WatchAsync</c> as ordinary .NET events on the
/// synchronization context captured at Start (a UI thread stand-in here), handler exceptions that never end the watch,
/// Stop and Dispose that wait for nothing.
/// </summary>
public sealed class HostLinkWatcherTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(30);
    private static readonly TimeSpan Fast = TimeSpan.FromMilliseconds(20);

    [Fact]
    public async Task Changes_are_raised_on_the_context_captured_at_Start_with_tag_old_new_and_time()
    {
        await using InProcessLine line = InProcessLine.Start();
        line.Plc.WriteWords("D100", new ushort[] { 7 });
        line.Plc.WriteWords("D200", SingleWords(1.5f));
        using var ui = new SingleThreadContext();
        var changes = new BlockingCollection<(TagValueChangedEventArgs Args, int Thread, object? Sender)>();
        using var watcher = new HostLinkWatcher(line.Client, new[] { "D100", "D200:float", "CIO 10.03" }, Fast);
        watcher.ValueChanged += (sender, e) => changes.Add((e, Environment.CurrentManagedThreadId, sender));

        await ui.Run(watcher.Start, Limit);

        var initial = Enumerable.Range(0, 3).Select(_ => Take(changes)).ToArray();
        initial.Select(c => c.Args.TagText).Should().Equal("D100", "D200:float", "CIO 10.03");
        initial.Should().OnlyContain(c => c.Thread == ui.ThreadId && c.Args.IsInitial && ReferenceEquals(c.Sender, watcher));
        initial[1].Args.NewValue.ToSingle().Should().Be(1.5f);

        DateTimeOffset before = DateTimeOffset.UtcNow;
        line.Plc.WriteWords("D200", SingleWords(2.5f));
        var change = Take(changes);
        change.Args.TagText.Should().Be("D200:float");
        change.Args.Index.Should().Be(1);
        change.Args.OldValue.Should().Be(PlcValue.FromSingle(1.5f));
        change.Args.NewValue.Should().Be(PlcValue.FromSingle(2.5f));
        change.Args.Timestamp.Should().BeOnOrAfter(before.AddSeconds(-1));
        change.Thread.Should().Be(ui.ThreadId);
        watcher.IsRunning.Should().BeTrue();
    }

    [Fact]
    public async Task A_handler_exception_goes_to_Error_and_the_watch_goes_on()
    {
        await using InProcessLine line = InProcessLine.Start();
        using var ui = new SingleThreadContext();
        var errors = new BlockingCollection<WatchErrorEventArgs>();
        var seen = new BlockingCollection<PlcValue>();
        using var watcher = new HostLinkWatcher(line.Client, new[] { "D100" }, Fast);
        watcher.ValueChanged += (_, e) =>
        {
            seen.Add(e.NewValue);
            if (e.IsInitial)
            {
                throw new InvalidOperationException("the label is gone");
            }
        };
        watcher.Error += (_, e) => errors.Add(e);

        await ui.Run(watcher.Start, Limit);

        Take(seen).Should().Be(PlcValue.FromWord(0));
        WatchErrorEventArgs error = Take(errors);
        error.Exception.Should().BeOfType<InvalidOperationException>().Which.Message.Should().Be("the label is gone");
        error.WatchEnded.Should().BeFalse();
        line.Plc.WriteWords("D100", new ushort[] { 5 });
        Take(seen).Should().Be(PlcValue.FromWord(5), "the watch went on after the handler threw");
        watcher.IsRunning.Should().BeTrue();
    }

    [Fact]
    public async Task Without_an_Error_handler_a_handler_exception_is_thrown_on_the_UI_thread_and_the_watch_goes_on()
    {
        await using InProcessLine line = InProcessLine.Start();
        var thrown = new BlockingCollection<(Exception Error, int Thread)>();
        using var ui = new SingleThreadContext { ThreadException = e => thrown.Add((e, Environment.CurrentManagedThreadId)) };
        var seen = new BlockingCollection<PlcValue>();
        using var watcher = new HostLinkWatcher(line.Client, new[] { "D100" }, Fast);
        watcher.ValueChanged += (_, e) =>
        {
            seen.Add(e.NewValue);
            throw new InvalidOperationException("handler bug " + e.NewValue);
        };

        await ui.Run(watcher.Start, Limit);

        Take(seen);
        var first = Take(thrown);
        first.Error.Message.Should().Be("handler bug 0x0000");
        first.Thread.Should().Be(ui.ThreadId, "as an exception from a Timer.Tick handler reaches Application.ThreadException");
        line.Plc.WriteWords("D100", new ushort[] { 1 });
        Take(seen).Should().Be(PlcValue.FromWord(1));
        Take(thrown).Error.Message.Should().Be("handler bug 0x0001");
    }

    [Fact]
    public async Task An_outage_is_ConnectionLost_then_ConnectionRestored_on_the_UI_thread()
    {
        await using InProcessLine line = InProcessLine.Start();
        line.Plc.WriteWords("D300", new ushort[] { 0x00A1 });
        using var ui = new SingleThreadContext();
        var events = new BlockingCollection<(string What, int Thread)>();
        using var watcher = new HostLinkWatcher(line.Client, new[] { "D300:bcd" }, new WatchOptions { Interval = Fast, RetryInterval = Fast });
        watcher.ConnectionLost += (_, e) => events.Add(("lost " + e.Exception.GetType().Name, Environment.CurrentManagedThreadId));
        watcher.ConnectionRestored += (_, e) => events.Add(("restored", Environment.CurrentManagedThreadId));
        watcher.ValueChanged += (_, e) => events.Add(("value " + e.NewValue, Environment.CurrentManagedThreadId));

        await ui.Run(watcher.Start, Limit);

        Take(events).Should().Be(("lost FormatException", ui.ThreadId), "a word that is not BCD fails the cycle");
        line.Plc.WriteWords("D300", new ushort[] { 0x0421 });
        Take(events).Should().Be(("restored", ui.ThreadId));
        Take(events).Should().Be(("value 421", ui.ThreadId));
    }

    [Fact]
    public async Task A_handler_slower_than_the_interval_shows_as_Overrun()
    {
        await using InProcessLine line = InProcessLine.Start();
        using var ui = new SingleThreadContext();
        var overruns = new BlockingCollection<WatchOverrunEventArgs>();
        var time = new Microsoft.Extensions.Time.Testing.FakeTimeProvider();
        using var watcher = new HostLinkWatcher(line.Client, new[] { "D100" }, new WatchOptions { Interval = TimeSpan.FromMilliseconds(50), TimeProvider = time });

        // The handler takes 200 ms of the watch's clock: the cycle outlasts its 50 ms interval.
        watcher.ValueChanged += (_, _) => time.Advance(TimeSpan.FromMilliseconds(200));
        watcher.Overrun += (_, e) => overruns.Add(e);

        await ui.Run(watcher.Start, Limit);

        Take(overruns).CycleTime.Should().BeGreaterThan(TimeSpan.FromMilliseconds(50));
    }

    [Fact]
    public async Task After_Stop_on_the_UI_thread_no_event_is_raised_and_Start_begins_again()
    {
        await using InProcessLine line = InProcessLine.Start();
        using var ui = new SingleThreadContext();
        var seen = new BlockingCollection<PlcValue>();
        using var watcher = new HostLinkWatcher(line.Client, new[] { "D100" }, Fast);
        watcher.ValueChanged += (_, e) => seen.Add(e.NewValue);
        await ui.Run(watcher.Start, Limit);
        Take(seen);

        await ui.Run(watcher.Stop, Limit);
        watcher.IsRunning.Should().BeFalse();
        line.Plc.WriteWords("D100", new ushort[] { 9 });

        // Several cycles' worth of proof that time passed: transactions on the same link, each queued behind any read
        // a watch still running would make, then the UI thread emptied of what was posted to it.
        for (int i = 0; i < 3; i++)
        {
            await line.Client.ReadWordsAsync("D100", 1);
        }

        await ui.Run(() => { }, Limit);
        seen.Should().BeEmpty("nothing is raised after Stop");

        await ui.Run(watcher.Start, Limit);
        Take(seen).Should().Be(PlcValue.FromWord(9), "a new watch reports every tag first");
    }

    [Fact]
    public async Task Bad_tags_are_refused_when_made_and_tags_the_command_set_cannot_reach_at_Start()
    {
        await using InProcessLine line = InProcessLine.Start();

        FluentActions.Invoking(() => new HostLinkWatcher(line.Client, new[] { "D100", "Q7" }, Fast)).Should().Throw<FormatException>();
        FluentActions.Invoking(() => new HostLinkWatcher(line.Client, Array.Empty<string>(), Fast)).Should().Throw<ArgumentException>();
        using var watcher = new HostLinkWatcher(line.Client, new[] { "W400.07" }, Fast);
        FluentActions.Invoking(watcher.Start).Should().Throw<ArgumentException>().WithMessage("*HostLinkCommandSet.Fins*");
        watcher.IsRunning.Should().BeFalse();
        line.FramesSent.Should().Be(0);
    }

    [Fact]
    public async Task Disposing_the_client_under_a_watch_ends_it_through_Error()
    {
        var (host, plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = new VirtualPlc().RunAsync(plcEnd, stop.Token);
        var client = HostLinkClient.ForStream(host, new HostLinkClientOptions { TurnaroundAllowance = InProcessLine.InMemoryAllowance });
        using var ui = new SingleThreadContext();
        var errors = new BlockingCollection<WatchErrorEventArgs>();
        var seen = new BlockingCollection<PlcValue>();
        using var watcher = new HostLinkWatcher(client, new[] { "D100" }, Fast);
        watcher.ValueChanged += (_, e) => seen.Add(e.NewValue);
        watcher.Error += (_, e) => errors.Add(e);
        await ui.Run(watcher.Start, Limit);
        Take(seen);

        client.Dispose();

        WatchErrorEventArgs error = Take(errors);
        error.WatchEnded.Should().BeTrue();
        error.Exception.Should().BeAssignableTo<Exception>();
        SpinWait.SpinUntil(() => !watcher.IsRunning, Limit).Should().BeTrue();
        stop.Cancel();
        await session;
    }

    [Fact]
    public async Task The_component_connects_from_its_properties_raises_on_the_UI_thread_reads_blocking_and_Dispose_closes_the_socket()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", new ushort[] { 12 });
        await using var server = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, 0));
        await server.StartAsync();
        using var ui = new SingleThreadContext();
        var changes = new BlockingCollection<(TagValueChangedEventArgs Args, int Thread, object? Sender)>();
        var component = new HostLinkPlc
        {
            Host = "127.0.0.1",
            TcpPort = server.EndPoint.Port,
            BaudRate = 115200,
            TurnaroundAllowance = InProcessLine.InMemoryAllowance,
            Tags = new[] { "D100", "D101:bcd" },
            Interval = 20,
        };
        component.ValueChanged += (sender, e) => changes.Add((e, Environment.CurrentManagedThreadId, sender));

        await ui.Run(component.Start, Limit);
        var first = Take(changes);
        first.Args.TagText.Should().Be("D100");
        first.Args.NewValue.Should().Be(PlcValue.FromWord(12));
        first.Thread.Should().Be(ui.ThreadId);
        first.Sender.Should().BeSameAs(component);
        Take(changes);
        component.IsWatching.Should().BeTrue();

        ushort[] words = [];
        await ui.Run(() => { component.Client.WriteBcd("D101", 77); words = component.Client.ReadWords("D100", 2); }, Limit);
        words.Should().Equal(12, 0x0077);
        Take(changes).Args.NewValue.Should().Be(PlcValue.FromBcd(77));
        FluentActions.Invoking(() => component.UnitNumber = 3).Should().Throw<InvalidOperationException>().WithMessage("UnitNumber cannot change*");

        component.Dispose();

        component.IsWatching.Should().BeFalse();
        SpinWait.SpinUntil(() => server.ActiveSessions == 0, Limit).Should().BeTrue("Dispose closed the socket");
        FluentActions.Invoking(() => component.Client).Should().Throw<ObjectDisposedException>();
    }

    [Fact]
    public void The_component_checks_its_properties_by_the_settings_rules_as_they_are_set()
    {
        using var component = new HostLinkPlc();

        FluentActions.Invoking(() => component.BaudRate = 9601).Should().Throw<ArgumentOutOfRangeException>().WithMessage("BaudRate: 9601 is not a standard rate*");
        FluentActions.Invoking(() => component.UnitNumber = 32).Should().Throw<ArgumentOutOfRangeException>().WithMessage("UnitNumber:*");
        FluentActions.Invoking(() => component.Interval = -1).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => component.Client).Should().Throw<InvalidOperationException>().WithMessage("Set PortName*or Host and TcpPort*");
        FluentActions.Invoking(component.Start).Should().Throw<InvalidOperationException>().WithMessage("Set Tags*");
        component.BaudRate.Should().Be(9600);
        component.DataBits.Should().Be(7);
        component.Parity.Should().Be(OmronHostLink.Transports.SerialParity.Even);
        component.StopBits.Should().Be(OmronHostLink.Transports.SerialStopBits.Two);
    }

    [Fact]
    public void The_component_sits_in_a_form_container_that_disposes_it()
    {
        using var container = new System.ComponentModel.Container();
        var component = new HostLinkPlc(container) { PortName = "/dev/null-port-that-is-never-opened" };
        _ = component.Client;

        container.Dispose();

        FluentActions.Invoking(() => component.Client).Should().Throw<ObjectDisposedException>();
    }

    private static ushort[] SingleWords(float value)
    {
        int bits = BitConverter.SingleToInt32Bits(value);
        return [(ushort)(bits & 0xFFFF), (ushort)((bits >> 16) & 0xFFFF)];
    }

    private static T Take<T>(BlockingCollection<T> items)
    {
        items.TryTake(out T? item, Limit).Should().BeTrue("the event came within {0}", Limit);
        return item!;
    }
}
