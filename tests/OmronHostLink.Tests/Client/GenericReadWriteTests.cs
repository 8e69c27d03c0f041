using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// ReadAsync&lt;T&gt; and WriteAsync&lt;T&gt; against the simulator: every supported type round-trips in both word orders and
/// both command sets, and the words in the PLC's memory match layouts computed here from <see cref="BitConverter"/> and
/// hand-written BCD digits, not by the library.
/// </summary>
public sealed class GenericReadWriteTests
{
    public static TheoryData<WordOrder, HostLinkCommandSet> OrdersAndCommandSets() => new()
    {
        { WordOrder.LowWordFirst, HostLinkCommandSet.CMode },
        { WordOrder.HighWordFirst, HostLinkCommandSet.CMode },
        { WordOrder.LowWordFirst, HostLinkCommandSet.Fins },
        { WordOrder.HighWordFirst, HostLinkCommandSet.Fins },
    };

    public static TheoryData<WordOrder> Orders() => new() { WordOrder.LowWordFirst, WordOrder.HighWordFirst };

    private static InProcessLine Start(WordOrder order, HostLinkCommandSet commandSet = HostLinkCommandSet.CMode)
        => InProcessLine.Start(new HostLinkClientOptions { WordOrder = order, CommandSet = commandSet });

    [Theory]
    [MemberData(nameof(OrdersAndCommandSets))]
    public async Task Every_type_round_trips_one_value_and_several(WordOrder order, HostLinkCommandSet commandSet)
    {
        // C-mode has no bit write: the C-mode client writes its bits by reading and writing back the words.
        await using InProcessLine line = InProcessLine.Start(new HostLinkClientOptions
        {
            WordOrder = order,
            CommandSet = commandSet,
            AllowReadModifyWriteBits = commandSet == HostLinkCommandSet.CMode,
        });
        HostLinkUnit plc = line.Client;

        await RoundTrip(plc, "CIO 10.14", true, false, true);
        await RoundTrip(plc, "D100", short.MinValue, (short)-1, (short)12345);
        await RoundTrip(plc, "D110", (ushort)65535, (ushort)0, (ushort)0x8000);
        await RoundTrip(plc, "D120", int.MinValue, -123456789, int.MaxValue);
        await RoundTrip(plc, "D130", uint.MaxValue, 3_000_000_000u, 1u);
        await RoundTrip(plc, "D140", 3.14159f, -1e-20f, float.MaxValue);
        await RoundTrip(plc, "D150", Math.PI, -2.5e300, double.Epsilon);
        await RoundTrip(plc, "D170", new Bcd16(9999), new Bcd16(0), new Bcd16(1234));
        await RoundTrip(plc, "D180", new Bcd32(99_999_999), new Bcd32(0), new Bcd32(12_345_678));

        // The bits crossed from CIO 10 into CIO 11.
        line.Plc.GetBit(PlcArea.Cio, 10, 14).Should().BeTrue();
        line.Plc.GetBit(PlcArea.Cio, 10, 15).Should().BeFalse();
        line.Plc.GetBit(PlcArea.Cio, 11, 0).Should().BeTrue();
    }

    [Theory]
    [MemberData(nameof(Orders))]
    public async Task Written_words_match_layouts_computed_from_BitConverter(WordOrder order)
    {
        await using InProcessLine line = Start(order);
        HostLinkUnit plc = line.Client;

        await plc.WriteAsync("D200", -123456789);
        await plc.WriteAsync("D202", 3_000_000_001u);
        await plc.WriteAsync("D204", -21.625f);
        await plc.WriteAsync("D206", -1.0e-7 * Math.PI);
        await plc.WriteAsync("D210", new Bcd32(12_345_678));

        line.Plc.ReadWords(PlcArea.Dm, 200, 2).Should().Equal(InOrder(BitConverter.GetBytes(-123456789), order));
        line.Plc.ReadWords(PlcArea.Dm, 202, 2).Should().Equal(InOrder(BitConverter.GetBytes(3_000_000_001u), order));
        line.Plc.ReadWords(PlcArea.Dm, 204, 2).Should().Equal(InOrder(BitConverter.GetBytes(-21.625f), order));
        line.Plc.ReadWords(PlcArea.Dm, 206, 4).Should().Equal(InOrder(BitConverter.GetBytes(-1.0e-7 * Math.PI), order));
        line.Plc.ReadWords(PlcArea.Dm, 210, 2).Should().Equal(order == WordOrder.LowWordFirst ? new ushort[] { 0x5678, 0x1234 } : new ushort[] { 0x1234, 0x5678 });
    }

    [Theory]
    [MemberData(nameof(Orders))]
    public async Task Words_seeded_in_memory_read_as_the_values_they_hold(WordOrder order)
    {
        await using InProcessLine line = Start(order);
        line.Plc.WriteWords(PlcArea.Dm, 300, InOrder(BitConverter.GetBytes(-987654321), order));
        line.Plc.WriteWords(PlcArea.Dm, 302, InOrder(BitConverter.GetBytes(6.02214076e23), order));
        line.Plc.WriteWords(PlcArea.Dm, 306, InOrder(BitConverter.GetBytes(0.1f), order));
        line.Plc.WriteWord(PlcArea.Dm, 308, 0x0042);

        (await line.Client.ReadAsync<int>("D300")).Should().Be(-987654321);
        (await line.Client.ReadAsync<double>("D302")).Should().Be(6.02214076e23);
        (await line.Client.ReadAsync<float>("D306")).Should().Be(0.1f);
        (await line.Client.ReadAsync<Bcd16>("D308")).Value.Should().Be(42);
        (await line.Client.ReadAsync<ushort>("D308")).Should().Be(0x42);
    }

    [Fact]
    public async Task A_view_with_the_other_word_order_shares_the_link()
    {
        await using InProcessLine line = Start(WordOrder.LowWordFirst);
        HostLinkUnit highFirst = line.Client.WithWordOrder(WordOrder.HighWordFirst);

        await highFirst.WriteAsync("D400", 2.5);

        highFirst.WordOrder.Should().Be(WordOrder.HighWordFirst);
        line.Client.WordOrder.Should().Be(WordOrder.LowWordFirst);
        line.Plc.ReadWords(PlcArea.Dm, 400, 4).Should().Equal(InOrder(BitConverter.GetBytes(2.5), WordOrder.HighWordFirst));
        (await line.Client.ReadAsync<double>("D400")).Should().NotBe(2.5, "the client reads the words low word first");
    }

    [Theory]
    [InlineData(HostLinkCommandSet.CMode)]
    [InlineData(HostLinkCommandSet.Fins)]
    public async Task Timer_and_counter_completion_flags_read_as_bools(HostLinkCommandSet commandSet)
    {
        await using InProcessLine line = Start(WordOrder.LowWordFirst, commandSet);
        line.Plc.SetFlag(PlcArea.Timer, 5, true);
        line.Plc.SetFlag(PlcArea.Timer, 7, true);
        line.Plc.SetFlag(PlcArea.Counter, 2, true);

        (await line.Client.ReadAsync<bool>("T5", 3)).Should().Equal(true, false, true);
        (await line.Client.ReadAsync<bool>("C2")).Should().BeTrue();
        (await line.Client.ReadAsync<bool>("C3")).Should().BeFalse();
    }

    [Fact]
    public async Task An_unsupported_type_is_refused_naming_it_and_the_supported_types_before_anything_is_sent()
    {
        await using InProcessLine line = Start(WordOrder.LowWordFirst);

        (await FluentActions.Awaiting(async () => await line.Client.ReadAsync<long>("D0")).Should().ThrowAsync<NotSupportedException>())
            .WithMessage("ReadAsync<Int64> is not supported*bool*short*ushort*int*uint*float*double*Bcd16*Bcd32*");
        (await FluentActions.Awaiting(async () => await line.Client.ReadAsync<decimal>("D0", 2)).Should().ThrowAsync<NotSupportedException>())
            .WithMessage("ReadAsync<Decimal>*");
        (await FluentActions.Awaiting(async () => await line.Client.WriteAsync("D0", DateTime.UnixEpoch)).Should().ThrowAsync<NotSupportedException>())
            .WithMessage("WriteAsync<DateTime>*");
        (await FluentActions.Awaiting(async () => await line.Client.WriteAsync("D0", new[] { 1L, 2L })).Should().ThrowAsync<NotSupportedException>())
            .WithMessage("WriteAsync<Int64>*");

        line.FramesSent.Should().Be(0);
    }

    [Fact]
    public async Task An_address_that_does_not_suit_the_type_is_refused_before_anything_is_sent()
    {
        await using InProcessLine line = Start(WordOrder.LowWordFirst);

        (await FluentActions.Awaiting(async () => await line.Client.ReadAsync<int>("D100.03")).Should().ThrowAsync<ArgumentException>())
            .WithMessage("D100.03 names a bit; a Int32 value takes 2 words from a word address such as D100.*");
        (await FluentActions.Awaiting(async () => await line.Client.WriteAsync("D100", true)).Should().ThrowAsync<ArgumentException>())
            .WithMessage("D100 names a word; Boolean values are bits*D100.05*");
        await FluentActions.Awaiting(async () => await line.Client.ReadAsync<double>("D32766")).Should().ThrowAsync<ArgumentException>();
        await FluentActions.Awaiting(async () => await line.Client.ReadAsync<short>("D0", 0)).Should().ThrowAsync<ArgumentOutOfRangeException>();
        await FluentActions.Awaiting(async () => await line.Client.WriteAsync("D0", ReadOnlyMemory<short>.Empty)).Should().ThrowAsync<ArgumentException>();
        await FluentActions.Awaiting(async () => await line.Client.ReadAsync<short>("Q7")).Should().ThrowAsync<FormatException>();
        FluentActions.Invoking(() => new Bcd16(10000)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => new Bcd32(-1)).Should().Throw<ArgumentOutOfRangeException>();

        line.FramesSent.Should().Be(0);
    }

    [Fact]
    public async Task Words_that_are_not_BCD_are_an_error_not_a_value()
    {
        await using InProcessLine line = Start(WordOrder.LowWordFirst);
        line.Plc.WriteWord(PlcArea.Dm, 10, 0x12A4);

        await FluentActions.Awaiting(async () => await line.Client.ReadAsync<Bcd16>("D10")).Should().ThrowAsync<FormatException>().WithMessage("0x12A4 is not BCD*");
    }

    [Fact]
    public async Task Several_values_are_one_read_and_one_write()
    {
        await using InProcessLine line = Start(WordOrder.LowWordFirst);

        await line.Client.WriteAsync("D500", new[] { 1.5, 2.5, 3.5 });
        (await line.Client.ReadAsync<double>("D500", 3)).Should().Equal(1.5, 2.5, 3.5);

        line.FramesSent.Should().Be(2);
    }

    /// <summary>The little-endian bytes of a value as words, lowest word first, then put in <paramref name="order"/>.</summary>
    private static ushort[] InOrder(byte[] littleEndian, WordOrder order)
    {
        BitConverter.IsLittleEndian.Should().BeTrue("the expectations read BitConverter's bytes as little-endian");
        var words = new ushort[littleEndian.Length / 2];
        for (int i = 0; i < words.Length; i++)
        {
            words[i] = (ushort)(littleEndian[2 * i] | (littleEndian[(2 * i) + 1] << 8));
        }

        return order == WordOrder.LowWordFirst ? words : words.Reverse().ToArray();
    }

    private static async Task RoundTrip<T>(HostLinkUnit plc, string address, params T[] values)
        where T : struct
    {
        await plc.WriteAsync(address, values[0]);
        (await plc.ReadAsync<T>(address)).Should().Be(values[0], "{0} written alone at {1}", typeof(T).Name, address);

        await plc.WriteAsync(address, values);
        (await plc.ReadAsync<T>(address, values.Length)).Should().Equal(values, "{0} written as a run at {1}", typeof(T).Name, address);
    }
}
