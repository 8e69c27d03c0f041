using System.Reflection;
using OmronHostLink.Planning;
using OmronHostLink.Protocol.Fins;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// Blocking on a call, as VB.NET and .NET Framework code does from a timer tick on the UI thread: <c>.Wait()</c>,
/// <c>.Result</c> and <c>.GetAwaiter().GetResult()</c> on every public async method give the value or the library's own
/// exception, and never deadlock while the caller blocks a single-threaded <see cref="SynchronizationContext"/>.
/// </summary>
public sealed class BlockingCallTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(60);

    public enum Blocking
    {
        Wait,
        Result,
        GetResult,
    }

    /// <summary>
    /// One call per public async method of <see cref="HostLinkUnit"/> (the C-mode client, or a FINS view of the same PLC
    /// for the FINS services and bit writes), in an order the simulator accepts.
    /// </summary>
    private static IEnumerable<(string Method, Func<HostLinkUnit, HostLinkUnit, Task> Call)> Calls() =>
    [
        ("WriteWordsAsync", (c, _) => c.WriteWordsAsync("D100", new ushort[] { 1, 2, 3 })),
        ("WriteWordsAsync", (c, _) => c.WriteWordsAsync(PlcAddress.Parse("D103"), new ushort[] { 4 })),
        ("WriteWordAsync", (c, _) => c.WriteWordAsync("D104", 5)),
        ("ReadWordsAsync", (c, _) => Expect(c.ReadWordsAsync("D100", 5), w => w.Should().Equal(1, 2, 3, 4, 5))),
        ("ReadWordsAsync", (c, _) => Expect(c.ReadWordsAsync(PlcAddress.Parse("D102"), 1), w => w.Should().Equal(3))),
        ("ReadWordAsync", (c, _) => Expect(c.ReadWordAsync("D104"), w => w.Should().Be(5))),
        ("WriteAsync", (c, _) => c.WriteAsync("D200", 2.5f)),
        ("WriteAsync", (c, _) => c.WriteAsync("D210", new[] { -1, 7 })),
        ("WriteAsync", (c, _) => c.WriteAsync("D220", new ReadOnlyMemory<short>(new short[] { -3 }))),
        ("ReadAsync", (c, _) => Expect(c.ReadAsync<float>("D200"), v => v.Should().Be(2.5f))),
        ("ReadAsync", (c, _) => Expect(c.ReadAsync<int>("D210", 2), v => v.Should().Equal(-1, 7))),
        ("WriteInt16Async", (c, _) => c.WriteInt16Async("D230", -12)),
        ("ReadInt16Async", (c, _) => Expect(c.ReadInt16Async("D230"), v => v.Should().Be(-12))),
        ("WriteUInt16Async", (c, _) => c.WriteUInt16Async("D231", 65000)),
        ("ReadUInt16Async", (c, _) => Expect(c.ReadUInt16Async("D231"), v => v.Should().Be(65000))),
        ("WriteInt32Async", (c, _) => c.WriteInt32Async("D232", -100000)),
        ("ReadInt32Async", (c, _) => Expect(c.ReadInt32Async("D232"), v => v.Should().Be(-100000))),
        ("WriteUInt32Async", (c, _) => c.WriteUInt32Async("D234", 4_000_000_000)),
        ("ReadUInt32Async", (c, _) => Expect(c.ReadUInt32Async("D234"), v => v.Should().Be(4_000_000_000))),
        ("WriteSingleAsync", (c, _) => c.WriteSingleAsync("D236", -0.25f)),
        ("ReadSingleAsync", (c, _) => Expect(c.ReadSingleAsync("D236"), v => v.Should().Be(-0.25f))),
        ("WriteBcdAsync", (c, _) => c.WriteBcdAsync("D238", 1234)),
        ("ReadBcdAsync", (c, _) => Expect(c.ReadBcdAsync("D238"), v => v.Should().Be(1234))),
        ("WriteStringAsync", (c, _) => c.WriteStringAsync("D240", "LOT42")),
        ("ReadStringAsync", (c, _) => Expect(c.ReadStringAsync("D240", 5), v => v.Should().Be("LOT42"))),
        ("WriteBitAsync", (_, f) => f.WriteBitAsync("CIO 10.03", true)),
        ("WriteBitAsync", (_, f) => f.WriteBitAsync(PlcAddress.Parse("CIO 10.04"), true)),
        ("ReadBitAsync", (c, _) => Expect(c.ReadBitAsync("CIO 10.03"), v => v.Should().BeTrue())),
        ("ReadBitAsync", (c, _) => Expect(c.ReadBitAsync(PlcAddress.Parse("CIO 10.05")), v => v.Should().BeFalse())),
        ("WriteBitsAsync", (_, f) => f.WriteBitsAsync(PlcAddress.Parse("CIO 11.00"), new[] { true, false, true })),
        ("ReadBitsAsync", (c, _) => Expect(c.ReadBitsAsync(PlcAddress.Parse("CIO 11.00"), 3), v => v.Should().Equal(true, false, true))),
        ("ReadTagsAsync", (c, _) => Expect(c.ReadTagsAsync(new[] { "D100", "D200:float" }), v => v.Should().HaveCount(2))),
        ("ReadTagsAsync", (c, _) => Expect(c.ReadTagsAsync(new[] { PlcTag.Parse("D104") }), v => v.Should().HaveCount(1))),
        ("ReadTagsAsync", (c, _) => Expect(c.ReadTagsAsync(new ReadPlanner().Plan(new[] { PlcTag.Parse("D101") }, 0)), v => v.Should().HaveCount(1))),
        ("ReadCompoundAsync", (c, _) => Expect(c.ReadCompoundAsync(new[] { "D100", "D104" }), v => v.Should().Equal(1, 5))),
        ("GetModelProfileAsync", (c, _) => c.GetModelProfileAsync()),
        ("ReadStatusAsync", (c, _) => Expect(c.ReadStatusAsync(), s => s.Mode.Should().Be(PlcMode.Program))),
        ("SetModeAsync", (c, _) => c.SetModeAsync(PlcMode.Monitor)),
        ("SetModeAsync", (c, _) => c.SetModeAsync(PlcMode.Program)),
        ("ReadErrorsAsync", (c, _) => c.ReadErrorsAsync()),
        ("ReadModelAsync", (c, _) => c.ReadModelAsync()),
        ("TestAsync", (c, _) => c.TestAsync()),
        ("ProbeAsync", (c, _) => Expect(c.ProbeAsync(), t => t.Should().NotBeNull())),
        ("InitializeAsync", (c, _) => c.InitializeAsync()),
        ("AbortAsync", (c, _) => c.AbortAsync()),
        ("ReadCpuUnitDataAsync", (_, f) => f.ReadCpuUnitDataAsync()),
        ("ReadCpuStatusAsync", (_, f) => f.ReadCpuStatusAsync()),
        ("ReadCycleTimeAsync", (_, f) => f.ReadCycleTimeAsync()),
        ("ReadClockAsync", (_, f) => f.ReadClockAsync()),
        ("WriteClockAsync", (_, f) => f.WriteClockAsync(new DateTime(2026, 1, 2, 3, 4, 5))),
        ("RunAsync", (_, f) => f.RunAsync(PlcMode.Monitor)),
        ("StopAsync", (_, f) => f.StopAsync()),
        ("ClearErrorsAsync", (_, f) => f.ClearErrorsAsync()),
        ("ReadErrorLogAsync", (_, f) => f.ReadErrorLogAsync(0, 5)),
        ("FillAsync", (_, f) => f.FillAsync("D300", 4, 9)),
        ("TransferAsync", (_, f) => f.TransferAsync("D300", "D310", 4)),
        ("ReadScatteredAsync", (_, f) => Expect(f.ReadScatteredAsync(new[] { "D310", "D313" }), v => v.Should().Equal(9, 9))),
        ("ForceBitAsync", (_, f) => f.ForceBitAsync("CIO 12.00", FinsForceAction.ForceSet)),
        ("CancelForcedBitsAsync", (_, f) => f.CancelForcedBitsAsync()),
    ];

    [Fact]
    public void Every_public_async_method_returns_a_Task_and_is_covered_here()
    {
        Type[] types = [typeof(HostLinkUnit), typeof(HostLinkClient), typeof(IHostLinkUnit), typeof(IHostLinkClient)];
        MethodInfo[] methods = types
            .SelectMany(t => t.GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.DeclaredOnly))
            .Where(m => m.Name.EndsWith("Async", StringComparison.Ordinal) && m.Name != nameof(HostLinkClient.DisposeAsync) && m.Name != nameof(HostLinkUnit.WatchAsync))
            .ToArray();

        methods.Where(m => m.ReturnType == typeof(ValueTask) || (m.ReturnType.IsGenericType && m.ReturnType.GetGenericTypeDefinition() == typeof(ValueTask<>)))
            .Select(m => $"{m.DeclaringType!.Name}.{m.Name}")
            .Should().BeEmpty("a ValueTask has no Wait(), and .Result on a pooled one throws; public methods return Task");
        HashSet<string> covered = Calls().Select(c => c.Method).ToHashSet();
        methods.Select(m => m.Name).Distinct().Where(n => !covered.Contains(n))
            .Should().BeEmpty("every public async method is called here with every kind of blocking (add a call to BlockingCallTests.Calls)");
    }

    [Theory]
    [InlineData(Blocking.Wait)]
    [InlineData(Blocking.Result)]
    [InlineData(Blocking.GetResult)]
    public async Task Every_public_async_method_gives_its_value_when_blocked_on_from_a_UI_thread(Blocking blocking)
    {
        await using InProcessLine line = InProcessLine.Start();
        HostLinkUnit fins = line.Client.Unit(0, HostLinkCommandSet.Fins);
        using var ui = new SingleThreadContext();
        var done = new List<string>();

        await ui.Run(
            () =>
            {
                SynchronizationContext.Current.Should().BeSameAs(ui);
                foreach ((string method, Func<HostLinkUnit, HostLinkUnit, Task> call) in Calls())
                {
                    Block(call(line.Client, fins), blocking);
                    done.Add(method);
                }
            },
            Limit);

        done.Should().HaveCount(Calls().Count());
        line.Plc.ReadWords("D313", 1)[0].Should().Be(9, "the FINS transfer ran");
    }

    [Fact]
    public async Task A_refusal_reaches_the_blocked_caller_as_the_library_exception()
    {
        await using InProcessLine line = InProcessLine.Start(
            new HostLinkClientOptions { TurnaroundAllowance = Allowances.LosslessLine, ReadRetries = 0 },
            new OmronHostLink.Simulator.VirtualPlcOptions { InitialMode = PlcMode.Run });
        using var ui = new SingleThreadContext();
        Exception? direct = null;
        Exception? wrapped = null;
        Exception? fromResult = null;

        await ui.Run(
            () =>
            {
                direct = Record.Exception(() => line.Client.WriteWordAsync("D0", 1).GetAwaiter().GetResult());
                wrapped = Record.Exception(() => line.Client.WriteWordAsync("D0", 1).Wait());
                fromResult = Record.Exception(() => _ = line.Client.Unit(9).ReadWordsAsync("D0", 1).Result);
            },
            Limit);

        direct.Should().BeOfType<HostLinkEndCodeException>("C-mode writes are refused in RUN mode (end code 01)");
        wrapped.Should().BeOfType<AggregateException>("Task.Wait() wraps, as Task semantics do")
            .Which.InnerException.Should().BeOfType<HostLinkEndCodeException>();
        fromResult.Should().BeOfType<AggregateException>()
            .Which.InnerException.Should().BeOfType<HostLinkTimeoutException>("unit 09 is not on the line");
    }

    [Fact]
    public async Task A_continuation_the_caller_awaits_comes_back_to_the_UI_thread()
    {
        await using InProcessLine line = InProcessLine.Start();
        using var ui = new SingleThreadContext();
        var resumedOn = new TaskCompletionSource<int>(TaskCreationOptions.RunContinuationsAsynchronously);

        await ui.Run(() => _ = ReadThenReportAsync(), Limit);

        (await resumedOn.Task.WaitAsync(Limit)).Should().Be(ui.ThreadId, "the library's ConfigureAwait(false) applies to its own awaits, not the caller's");

        async Task ReadThenReportAsync()
        {
            await line.Client.ReadWordsAsync("D0", 1);
            resumedOn.SetResult(Environment.CurrentManagedThreadId);
        }
    }

    private static Task Expect<T>(Task<T> call, Action<T> check) => ExpectAsync(call, check);

    private static async Task<T> ExpectAsync<T>(Task<T> call, Action<T> check)
    {
        T value = await call.ConfigureAwait(false);
        check(value);
        return value;
    }

    private static void Block(Task task, Blocking blocking)
    {
        switch (blocking)
        {
            case Blocking.Wait:
                task.Wait();
                break;
            case Blocking.GetResult:
                task.GetAwaiter().GetResult();
                break;
            default:
                if (task.GetType().GetProperty("Result") is { } result)
                {
                    try
                    {
                        _ = result.GetValue(task);
                    }
                    catch (TargetInvocationException e)
                    {
                        throw e.InnerException!;
                    }
                }
                else
                {
                    task.Wait();
                }

                break;
        }
    }
}
