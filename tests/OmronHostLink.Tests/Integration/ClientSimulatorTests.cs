using System.Net;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Integration;

/// <summary>The client against the simulator, end to end: over TCP loopback and over a real pseudo-terminal pair.</summary>
public sealed class ClientSimulatorTests
{
    public enum Wire
    {
        Tcp,
        Pty,
    }

    private static HostLinkClientOptions Options(HostLinkCommandSet protocol = HostLinkCommandSet.CMode) => new()
    {
        LineTiming = new LineTiming(115200, 11),
        TurnaroundAllowance = Allowances.LosslessLine,
        // The silent unit of the multidrop test costs one allowance, not three.
        ReadRetries = 0,
        CommandSet = protocol,
    };

    /// <summary>A simulator and a client connected to it over the chosen wire.</summary>
    private sealed class Rig : IAsyncDisposable
    {
        private readonly List<IAsyncDisposable> _parts = new();

        public required VirtualPlc Plc { get; init; }

        public HostLinkClient Client { get; private set; } = null!;

        public static async Task<Rig> StartAsync(Wire wire, HostLinkCommandSet protocol = HostLinkCommandSet.CMode, VirtualPlcOptions? plcOptions = null)
        {
            var rig = new Rig { Plc = new VirtualPlc(plcOptions ?? new VirtualPlcOptions { Units = new[] { 0, 3 } }) };
            if (wire == Wire.Tcp)
            {
                var host = new TcpSimulatorHost(rig.Plc, new IPEndPoint(IPAddress.Loopback, 0));
                await host.StartAsync();
                rig._parts.Add(host);
                rig.Client = HostLinkClient.ForTcp("127.0.0.1", host.EndPoint.Port, Options(protocol));
            }
            else
            {
                SocatPtyPair pty = await SocatPtyPair.StartAsync();
                rig._parts.Add(pty);
                var host = new SerialSimulatorHost(rig.Plc, new SerialLineSettings { PortName = pty.PathB });
                await host.StartAsync();
                rig._parts.Insert(0, host);
                rig.Client = HostLinkClient.ForSerialPort(new SerialLineSettings { PortName = pty.PathA, BaudRate = 115200 }, Options(protocol));
            }

            return rig;
        }

        public async ValueTask DisposeAsync()
        {
            await Client.DisposeAsync();
            foreach (IAsyncDisposable part in _parts)
            {
                await part.DisposeAsync();
            }
        }
    }

    public static IEnumerable<object[]> Wires => new[] { new object[] { Wire.Tcp }, new object[] { Wire.Pty } };

    public static IEnumerable<object[]> WiresAndProtocols =>
        from w in new[] { Wire.Tcp, Wire.Pty }
        from p in new[] { HostLinkCommandSet.CMode, HostLinkCommandSet.Fins }
        select new object[] { w, p };

    [Theory]
    [MemberData(nameof(WiresAndProtocols))]
    public async Task Every_area_round_trips(Wire wire, HostLinkCommandSet protocol)
    {
        await using Rig rig = await Rig.StartAsync(wire, protocol);
        string[] addresses = protocol == HostLinkCommandSet.CMode
            ? new[] { "D100", "CIO 200", "H10", "A448", "T5", "C7", "E1_100", "EC_9990" }
            : new[] { "D100", "D20000", "CIO 200", "W30", "H10", "A448", "T3000", "C7", "E1_30000", "EC_9990" };
        ushort value = 0x1234;
        foreach (string address in addresses)
        {
            ushort[] words = { value, (ushort)(value + 1), (ushort)(value + 2) };
            await rig.Client.WriteWordsAsync(address, words);
            (await rig.Client.ReadWordsAsync(address, 3)).Should().Equal(words, address);
            PlcAddress a = PlcAddress.Parse(address);
            rig.Plc.ReadWords(a.Area, a.Word, 3, a.Bank).Should().Equal(words, $"{address} is in the PLC's memory");
            value += 0x1111;
        }
    }

    [Theory]
    [MemberData(nameof(WiresAndProtocols))]
    public async Task A_1000_word_read_and_a_200_word_write(Wire wire, HostLinkCommandSet protocol)
    {
        await using Rig rig = await Rig.StartAsync(wire, protocol);
        ushort[] seeded = Enumerable.Range(0, 1000).Select(i => (ushort)(i * 7)).ToArray();
        rig.Plc.WriteWords(PlcArea.Dm, 2000, seeded);

        (await rig.Client.ReadWordsAsync("D2000", 1000)).Should().Equal(seeded);

        ushort[] written = Enumerable.Range(0, 200).Select(i => (ushort)(0xF000 + i)).ToArray();
        await rig.Client.WriteWordsAsync("D5000", written);
        rig.Plc.ReadWords(PlcArea.Dm, 5000, 200).Should().Equal(written);
    }

    [Theory]
    [MemberData(nameof(WiresAndProtocols))]
    public async Task Mode_changes_and_status(Wire wire, HostLinkCommandSet protocol)
    {
        await using Rig rig = await Rig.StartAsync(wire, protocol);

        await rig.Client.SetModeAsync(PlcMode.Monitor);
        rig.Plc.Mode.Should().Be(PlcMode.Monitor);
        (await rig.Client.ReadStatusAsync()).Mode.Should().Be(PlcMode.Monitor);

        await rig.Client.SetModeAsync(PlcMode.Run);
        (await rig.Client.ReadStatusAsync()).Mode.Should().Be(PlcMode.Run);

        await rig.Client.SetModeAsync(PlcMode.Program);
        rig.Plc.Mode.Should().Be(PlcMode.Program);

        // MS reports UM protection in its status word; FINS CONTROLLER STATUS READ has no status word to report it.
        rig.Plc.UserMemoryWriteProtected = true;
        PlcStatus status = await rig.Client.ReadStatusAsync();
        if (protocol == HostLinkCommandSet.Fins)
        {
            status.StatusWord.Should().BeNull();
            status.UserMemoryWritable.Should().BeNull();
        }
        else
        {
            status.UserMemoryWritable.Should().BeFalse();
            rig.Plc.UserMemoryWriteProtected = false;
            (await rig.Client.ReadStatusAsync()).UserMemoryWritable.Should().BeTrue();
        }
    }

    [Theory]
    [MemberData(nameof(Wires))]
    public async Task C_mode_writes_are_refused_in_RUN_with_end_code_01_and_nothing_changes(Wire wire)
    {
        await using Rig rig = await Rig.StartAsync(wire);
        rig.Plc.Mode = PlcMode.Run;

        var e = await FluentActions.Awaiting(() => rig.Client.WriteWordAsync("D10", 99)).Should().ThrowAsync<HostLinkEndCodeException>();

        e.Which.EndCode.Should().Be(EndCode.NotExecutableInRunMode);
        rig.Plc.ReadWord(PlcArea.Dm, 10).Should().Be(0);
    }

    [Theory]
    [MemberData(nameof(Wires))]
    public async Task Errors_model_test_and_multidrop(Wire wire)
    {
        await using Rig rig = await Rig.StartAsync(wire);
        rig.Plc.SetError(0x8000, 0x0001);

        PlcErrorInfo errors = await rig.Client.ReadErrorsAsync(clear: true);
        errors.FirstWord.Should().Be(0x8000);
        errors.SecondWord.Should().Be(0x0001);
        (await rig.Client.ReadErrorsAsync()).HasErrors.Should().BeFalse();

        (await rig.Client.ReadModelAsync()).Name.Should().Be("CS/CJ");
        (await rig.Client.TestAsync("HELLO 123")).Should().BePositive();

        rig.Plc.WriteWords(PlcArea.Dm, 0, new ushort[] { 42 });
        (await rig.Client.Unit(3).ReadWordsAsync("D0", 1)).Should().Equal(new ushort[] { 42 });
        await FluentActions.Awaiting(() => rig.Client.Unit(4).ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>("the simulator owns units 0 and 3 only");
        (await rig.Client.ReadWordsAsync("D0", 1)).Should().Equal(new ushort[] { 42 }, "the link resynchronises after the silent unit");
    }

    [Fact]
    public async Task Typed_values_and_bits_round_trip()
    {
        await using Rig rig = await Rig.StartAsync(Wire.Tcp);
        await rig.Client.WriteInt32Async("D0", -123456);
        (await rig.Client.ReadInt32Async("D0")).Should().Be(-123456);
        rig.Plc.ReadWords(PlcArea.Dm, 0, 2).Should().Equal(unchecked((ushort)(-123456 & 0xFFFF)), unchecked((ushort)((-123456 >> 16) & 0xFFFF)));
        await rig.Client.WriteSingleAsync("D2", 21.5f);
        (await rig.Client.ReadSingleAsync("D2")).Should().Be(21.5f);
        await rig.Client.WriteBcdAsync("D4", 1234);
        rig.Plc.ReadWord(PlcArea.Dm, 4).Should().Be(0x1234);
        (await rig.Client.ReadBcdAsync("D4")).Should().Be(1234);
        await rig.Client.WriteStringAsync("D10", "HELLO");
        (await rig.Client.ReadStringAsync("D10", 5)).Should().Be("HELLO");

        await rig.Client.Unit(0, HostLinkCommandSet.Fins).WriteBitAsync("CIO 100.05", true);
        rig.Plc.GetBit(PlcArea.Cio, 100, 5).Should().BeTrue();
        (await rig.Client.ReadBitAsync("CIO100.05")).Should().BeTrue();
        rig.Plc.SetFlag(PlcArea.Timer, 5, true);
        (await rig.Client.ReadBitAsync("T5")).Should().BeTrue();
    }
}
