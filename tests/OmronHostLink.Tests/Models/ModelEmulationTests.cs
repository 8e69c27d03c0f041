using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// Every profile against the simulator emulating it: the first and last word of each of its ranges read right, one past
/// the last is refused before anything is sent, and what the model lacks (FINS) is refused before the wire too.
/// </summary>
public sealed class ModelEmulationTests
{
    public static TheoryData<string> ProfileNames()
    {
        var names = new TheoryData<string>();
        foreach (var profile in PlcModelProfile.All)
        {
            names.Add(profile.Name);
        }

        return names;
    }

    [Theory]
    [MemberData(nameof(ProfileNames))]
    public async Task Edge_addresses_read_right_and_one_past_the_last_is_refused_before_the_wire(string name)
    {
        var profile = PlcModelProfile.Parse(name);
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = name });
        await using var line = await EmulatedLine.StartAsync(plc, name);
        ushort value = 0x1000;
        foreach (var (area, first, last, bank) in Extents(profile))
        {
            var set = CommandSetFor(profile, area, last);
            if (set is null)
            {
                continue; // beyond C-mode on a model without FINS: no command reaches it.
            }

            var unit = line.Client.Unit(0, set.Value);
            foreach (var word in new[] { first, last })
            {
                var address = PlcAddress.WordOf(area, word, bank);
                value++;
                plc.WriteWord(area, word, value, bank);
                (await unit.ReadWordsAsync(address, 1)).Should().Equal(new[] { value }, $"{name} has {address}");
            }

            if (last + 1 < PlcAddress.AreaSize(area))
            {
                var beyond = PlcAddress.WordOf(area, last + 1, bank);
                if (profile.Contains(beyond))
                {
                    continue; // the next range of the area starts right after (a change of write access)
                }

                var beyondSet = CommandSetFor(profile, area, last + 1);
                if (beyondSet is null)
                {
                    continue;
                }

                var beyondUnit = line.Client.Unit(0, beyondSet.Value);
                long sent = line.BytesSent;
                await FluentActions.Awaiting(() => beyondUnit.ReadWordsAsync(beyond, 1)).Should()
                    .ThrowAsync<ArgumentException>($"{name} has no {beyond}")
                    .WithMessage($"*{profile.DisplayName}*");
                line.BytesSent.Should().Be(sent, $"the read of {beyond} is refused before the wire");
            }
        }
    }

    [Theory]
    [MemberData(nameof(ProfileNames))]
    public async Task A_model_without_FINS_is_sent_no_FA_frame_and_the_simulator_answers_one_with_IC(string name)
    {
        var profile = PlcModelProfile.Parse(name);
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = name });
        await using var line = await EmulatedLine.StartAsync(plc, name);
        var fins = line.Client.Unit(0, HostLinkCommandSet.Fins);

        if (profile.SupportsFins)
        {
            plc.WriteWord(PlcArea.Dm, 0, 0x4321);
            (await fins.ReadWordsAsync("D0", 1)).Should().Equal((ushort)0x4321);
            return;
        }

        long sent = line.BytesSent;
        await FluentActions.Awaiting(() => fins.ReadWordsAsync("D0", 1)).Should().ThrowAsync<NotSupportedException>()
            .WithMessage($"*{profile.DisplayName} does not take FINS*");
        await FluentActions.Awaiting(() => fins.ReadCpuStatusAsync()).Should().ThrowAsync<NotSupportedException>();
        line.BytesSent.Should().Be(sent);

        await using RawHost raw = RawHost.Start(new VirtualPlcOptions { Model = name });
        (await raw.TransactAsync(RawHost.Command("@00FA000000000010182000000000001"))).Should().Be(RawHost.Command("@00IC"));
    }

    [Theory]
    [InlineData("CP2E", "QQ")]
    [InlineData("CP2E", "RL")]
    [InlineData("CP1E-E", "RE")]
    [InlineData("CPM2A", "QQ")]
    [InlineData("C200HS", "RE")]
    public async Task The_simulator_answers_a_command_the_model_lacks_with_IC(string model, string header)
    {
        await using RawHost raw = RawHost.Start(new VirtualPlcOptions { Model = model });

        (await raw.TransactAsync(RawHost.Command("@00" + header + "00000001"))).Should().Be(RawHost.Command("@00IC"));
    }

    [Fact]
    public async Task A_C200HS_simulator_answers_DM_it_does_not_have_with_0000_and_refuses_what_RD_cannot_name()
    {
        // C200HS Operation Manual p409, RD note 2: DM 6656–6999 do not exist; reading them returns 0000, no error.
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "C200HS" });
        plc.WriteWord(PlcArea.Dm, 6655, 0x1234);
        plc.WriteWord(PlcArea.Dm, 6656, 0x5678);
        await using RawHost raw = RawHost.Start(plc);

        (await raw.TransactAsync(RawHost.Command("@00RD66550002"))).Should().Be(RawHost.Command("@00RD0012340000"));
        (await raw.TransactAsync(RawHost.Command("@00MM"))).Should().Be(RawHost.Command("@00MM0012"));
        (await raw.TransactAsync(RawHost.Command("@00RC05120001"))).Should().Be(RawHost.Command("@00RC15"));
    }

    [Theory]
    [InlineData("C200HS", 0x12)]
    [InlineData("C200HX", 0x12)]
    [InlineData("C200H", 0x12)]
    [InlineData("CQM1", 0x11)]
    [InlineData("CQM1H", 0x11)]
    [InlineData("CPM1A", 0x11)]
    [InlineData("CPM2A", 0x11)]
    [InlineData("SRM1", 0x11)]
    [InlineData("CS1", 0x30)]
    public async Task A_client_with_model_auto_detects_the_family_from_MM_on_first_use(string model, byte code)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        await using var line = await EmulatedLine.StartAsync(plc, "auto");

        var detected = await line.Client.GetModelProfileAsync();

        detected.Should().BeSameAs(PlcModelProfile.FromModelCode(code));
        detected!.ModelCode.Should().Be(code);
        long sent = line.BytesSent;
        (await line.Client.GetModelProfileAsync()).Should().BeSameAs(detected, "MM is asked once per unit");
        line.BytesSent.Should().Be(sent);
    }

    [Theory]
    [InlineData("CP1E-E")]
    [InlineData("CP2E")]
    [InlineData("CP1H")]
    public async Task A_model_whose_MM_code_no_manual_gives_answers_IC_and_the_client_checks_without_a_model(string model)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        await using var line = await EmulatedLine.StartAsync(plc, "auto");

        (await line.Client.GetModelProfileAsync()).Should().BeNull();
        plc.WriteWord(PlcArea.Dm, 100, 7);
        (await line.Client.ReadWordsAsync("D100", 1)).Should().Equal((ushort)7);
    }

    [Fact]
    public async Task A_client_with_model_auto_refuses_the_read_a_C200HS_would_answer_with_0000()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "C200HS" });
        plc.WriteWord(PlcArea.Dm, 6656, 0x5678);

        // Without a model the read goes out and the PLC's 0000 comes back as if it were a value: the hazard.
        await using (var unchecked_ = await EmulatedLine.StartAsync(plc, null))
        {
            (await unchecked_.Client.ReadWordsAsync("D6656", 1)).Should().Equal((ushort)0);
        }

        await using var line = await EmulatedLine.StartAsync(plc, "auto");
        await line.Client.ReadWordsAsync("D100", 1); // first use: MM
        long sent = line.BytesSent;

        var e = await FluentActions.Awaiting(() => line.Client.ReadWordsAsync("D6656", 1)).Should().ThrowAsync<ArgumentOutOfRangeException>();

        e.Which.Message.Should().StartWith("D6656 is beyond the DM area of a PLC answering MM 12 (C200H, C200HS, C200HX/HG/HE");
        line.BytesSent.Should().Be(sent);
    }

    [Fact]
    public async Task A_configured_model_refuses_before_the_wire_in_the_users_words()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CP1E-E" });
        await using var line = await EmulatedLine.StartAsync(plc, "CP1E-E");

        var e = await FluentActions.Awaiting(() => line.Client.ReadWordsAsync("D2048", 1)).Should().ThrowAsync<ArgumentOutOfRangeException>();

        e.Which.Message.Should().StartWith("D2048 is beyond the DM area of a CP1E E-type (D0–D2047).");
        line.BytesSent.Should().Be(0);
    }

    [Fact]
    public async Task Counters_of_a_shared_TC_space_are_read_with_RC_at_their_own_number()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        plc.WriteWord(PlcArea.Counter, 5, 0x0042);
        await using RawHost raw = RawHost.Start(plc);
        (await raw.TransactAsync(RawHost.Command("@00RC00050001"))).Should().Be(RawHost.Command("@00RC000042"));

        var plc2 = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        plc2.WriteWord(PlcArea.Timer, 5, 0x0042);
        await using var line = await EmulatedLine.StartAsync(plc2, "CPM1A");
        (await line.Client.ReadWordsAsync("C5", 1)).Should().Equal((ushort)0x0042);
        (await line.Client.ReadWordsAsync("TC5", 1)).Should().Equal((ushort)0x0042);
    }

    [Fact]
    public async Task QQ_is_refused_before_the_wire_on_a_model_without_it_and_answered_on_one_with_it()
    {
        var cp2e = new VirtualPlc(new VirtualPlcOptions { Model = "CP2E" });
        await using (var line = await EmulatedLine.StartAsync(cp2e, "CP2E"))
        {
            await FluentActions.Awaiting(() => line.Client.ReadCompoundAsync(["D0", "D1"])).Should().ThrowAsync<NotSupportedException>()
                .WithMessage("A CP2E does not accept the C-mode compound read (QQ).");
            line.BytesSent.Should().Be(0);
        }

        var cpm1a = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        cpm1a.WriteWord(PlcArea.Dm, 6144, 0x0102);
        await using (var line = await EmulatedLine.StartAsync(cpm1a, "CPM1A"))
        {
            await FluentActions.Awaiting(() => line.Client.ReadCompoundAsync(["D0", "D2000"])).Should().ThrowAsync<ArgumentOutOfRangeException>()
                .WithMessage("D2000 is beyond the DM area of a CPM1/CPM1A*");
            line.BytesSent.Should().Be(0);
        }
    }

    [Fact]
    public void An_unknown_model_is_refused_when_the_options_are_checked()
    {
        var options = new HostLinkClientOptions { Model = "CPM9" };
        FluentActions.Invoking(options.Validate).Should().Throw<ArgumentException>()
            .WithMessage("Model 'CPM9' is not a known PLC model; use one of C200H, *, or auto to ask the PLC (MM).*");
        FluentActions.Invoking(() => new VirtualPlc(new VirtualPlcOptions { Model = "CPM9" })).Should().Throw<ArgumentException>();
    }

    // The ranges of each area, adjacent ones joined, with the EM bank to use (the last one the model has).
    private static IEnumerable<(PlcArea Area, int First, int Last, int Bank)> Extents(PlcModelProfile profile)
    {
        PlcAreaRange? open = null;
        int first = 0;
        foreach (var range in profile.Areas)
        {
            if (open is not null && range.Area == open.Area && range.First == open.Last + 1)
            {
                open = range;
                continue;
            }

            if (open is not null)
            {
                yield return (open.Area, first, open.Last, Math.Max(0, open.BankCount - 1));
            }

            open = range;
            first = range.First;
        }

        if (open is not null)
        {
            yield return (open.Area, first, open.Last, Math.Max(0, open.BankCount - 1));
        }
    }

    // C-mode where it reaches the whole range (W342 p128: D/EM to 9999, T/C to 2047, no W); FINS otherwise, if the model has it.
    private static HostLinkCommandSet? CommandSetFor(PlcModelProfile profile, PlcArea area, int last)
    {
        bool cmode = area switch
        {
            PlcArea.Work => false,
            PlcArea.Dm or PlcArea.Em => last < 10000,
            PlcArea.Timer or PlcArea.Counter => last < 2048,
            _ => true,
        };
        return cmode ? HostLinkCommandSet.CMode : profile.SupportsFins ? HostLinkCommandSet.Fins : null;
    }

    /// <summary>A client (with <c>Model</c> set as given) on an in-memory line to a simulated PLC, counting the bytes it sends.</summary>
    private sealed class EmulatedLine : IAsyncDisposable
    {
        private readonly CancellationTokenSource _stop = new();
        private readonly CountingStream _host;

        private EmulatedLine(VirtualPlc plc, string? model)
        {
            (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
            _host = new CountingStream(host);
            _ = plc.RunAsync(plcEnd, _stop.Token);
            Client = HostLinkClient.ForStream(_host, new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = Allowances.LosslessLine, Model = model });
        }

        public HostLinkClient Client { get; }

        public long BytesSent => _host.Written;

        public static Task<EmulatedLine> StartAsync(VirtualPlc plc, string? model) => Task.FromResult(new EmulatedLine(plc, model));

        public async ValueTask DisposeAsync()
        {
            await Client.DisposeAsync();
            _stop.Cancel();
            _stop.Dispose();
        }
    }

    private sealed class CountingStream(Stream inner) : Stream
    {
        private long _written;

        public long Written => Interlocked.Read(ref _written);

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => true;

        public override long Length => throw new NotSupportedException();

        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }

        public override void Flush() => inner.Flush();

        public override Task FlushAsync(CancellationToken cancellationToken) => inner.FlushAsync(cancellationToken);

        public override int Read(byte[] buffer, int offset, int count) => inner.Read(buffer, offset, count);

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default) => inner.ReadAsync(buffer, cancellationToken);

        public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken) => inner.ReadAsync(buffer, offset, count, cancellationToken);

        public override void Write(byte[] buffer, int offset, int count)
        {
            Interlocked.Add(ref _written, count);
            inner.Write(buffer, offset, count);
        }

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            Interlocked.Add(ref _written, buffer.Length);
            return inner.WriteAsync(buffer, cancellationToken);
        }

        public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
        {
            Interlocked.Add(ref _written, count);
            return inner.WriteAsync(buffer, offset, count, cancellationToken);
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        protected override void Dispose(bool disposing)
        {
            if (disposing)
            {
                inner.Dispose();
            }

            base.Dispose(disposing);
        }
    }
}
