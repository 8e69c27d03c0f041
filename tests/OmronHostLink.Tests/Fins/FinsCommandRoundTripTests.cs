using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Fins;

/// <summary>Encode → frame → parse round trips of every command type, with random values from a seeded Random.</summary>
public class FinsCommandRoundTripTests
{
    private const int Iterations = 200;

    private static readonly byte[] WordAreas = { 0xB0, 0xB1, 0xB2, 0xB3, 0x82, 0x89, 0xA0, 0xA5, 0xAC, 0x98 };
    private static readonly byte[] BitAreas = { 0x30, 0x31, 0x32, 0x33, 0x02, 0x09, 0x20, 0x2C, 0x0A };

    private static FinsMemoryAddress WordAddress(Random r) => new(WordAreas[r.Next(WordAreas.Length)], r.Next(0, 65536));

    private static FinsMemoryAddress BitAddress(Random r) => new(BitAreas[r.Next(BitAreas.Length)], r.Next(0, 65536), r.Next(0, 16));

    private static FinsMemoryAddress AnyAddress(Random r) => r.Next(2) == 0 ? WordAddress(r) : BitAddress(r);

    private static FinsHeader Header(Random r)
        => r.Next(2) == 0
            ? FinsHeader.Direct(r.Next(256), r.Next(16))
            : FinsHeader.Network(r.Next(128), r.Next(256), r.Next(256), r.Next(128), r.Next(256), r.Next(256), r.Next(256), r.Next(8), r.Next(16));

    private static DateTime Time(Random r)
        => new DateTime(1970, 1, 1).AddSeconds(r.NextDouble() * (new DateTime(2069, 12, 31, 23, 59, 59) - new DateTime(1970, 1, 1)).TotalSeconds);

    public static IEnumerable<object[]> Generators()
    {
        yield return new object[] { "0101 words", (Func<Random, FinsCommand>)(r => new MemoryAreaReadCommand(WordAddress(r), r.Next(0, MemoryAreaReadCommand.MaxWords + 1))) };
        yield return new object[] { "0101 bits", (Func<Random, FinsCommand>)(r => new MemoryAreaReadCommand(BitAddress(r), r.Next(0, MemoryAreaReadCommand.MaxBits + 1))) };
        yield return new object[] { "0102 words", (Func<Random, FinsCommand>)(r => MemoryAreaWriteCommand.Words(WordAddress(r), Enumerable.Range(0, r.Next(0, MemoryAreaWriteCommand.MaxWords + 1)).Select(_ => (ushort)r.Next(65536)).ToArray())) };
        yield return new object[] { "0102 bits", (Func<Random, FinsCommand>)(r => MemoryAreaWriteCommand.Bits(BitAddress(r), Enumerable.Range(0, r.Next(0, 100)).Select(_ => r.Next(2) == 1).ToArray())) };
        yield return new object[] { "0103", (Func<Random, FinsCommand>)(r => new MemoryAreaFillCommand(WordAddress(r), r.Next(65536), (ushort)r.Next(65536))) };
        yield return new object[] { "0104", (Func<Random, FinsCommand>)(r => new MultipleMemoryAreaReadCommand(Enumerable.Range(0, r.Next(1, 100)).Select(_ => AnyAddress(r)).ToArray())) };
        yield return new object[] { "0105", (Func<Random, FinsCommand>)(r => new MemoryAreaTransferCommand(WordAddress(r), WordAddress(r), r.Next(65536))) };
        yield return new object[]
        {
            "0401",
            (Func<Random, FinsCommand>)(r => r.Next(3) switch
            {
                0 => new RunCommand(null, null),
                1 => new RunCommand((ushort)r.Next(65536), null),
                _ => new RunCommand((ushort)r.Next(65536), r.Next(2) == 0 ? FinsCpuMode.Monitor : FinsCpuMode.Run),
            }),
        };
        yield return new object[] { "0402", (Func<Random, FinsCommand>)(r => r.Next(2) == 0 ? new StopCommand(null) : new StopCommand((ushort)r.Next(65536))) };
        yield return new object[] { "0501", (Func<Random, FinsCommand>)(r => r.Next(2) == 0 ? new CpuUnitDataReadCommand() : new CpuUnitDataReadCommand((byte)r.Next(256))) };
        yield return new object[] { "0601", (Func<Random, FinsCommand>)(_ => FinsCommands.CpuUnitStatusReadCommand) };
        yield return new object[] { "0620", (Func<Random, FinsCommand>)(r => new CycleTimeReadCommand(r.Next(2) == 0)) };
        yield return new object[] { "0701", (Func<Random, FinsCommand>)(_ => FinsCommands.ClockReadCommand) };
        yield return new object[]
        {
            "0702",
            (Func<Random, FinsCommand>)(r => r.Next(3) switch
            {
                0 => new ClockWriteCommand(Time(r), includeSecond: false, dayOfWeek: null),
                1 => new ClockWriteCommand(Time(r), includeSecond: true, dayOfWeek: null),
                _ => new ClockWriteCommand(Time(r), includeSecond: true, (DayOfWeek)r.Next(7)),
            }),
        };
        yield return new object[] { "2101", (Func<Random, FinsCommand>)(r => new ErrorClearCommand((ushort)r.Next(65536))) };
        yield return new object[] { "2102", (Func<Random, FinsCommand>)(r => new ErrorLogReadCommand(r.Next(65536), r.Next(1, ErrorLogReadCommand.MaxRecords + 1))) };
        yield return new object[]
        {
            "2301",
            (Func<Random, FinsCommand>)(r => new ForcedSetResetCommand(Enumerable.Range(0, r.Next(1, ForcedSetResetCommand.MaxItems + 1))
                .Select(_ => new FinsForcedBit(
                    new[] { FinsForceAction.ForceReset, FinsForceAction.ForceSet, FinsForceAction.ReleaseToOff, FinsForceAction.ReleaseToOn, FinsForceAction.Release }[r.Next(5)],
                    BitAddress(r)))
                .ToArray())),
        };
        yield return new object[] { "2302", (Func<Random, FinsCommand>)(_ => FinsCommands.ForcedCancelCommand) };
        yield return new object[]
        {
            "raw",
            (Func<Random, FinsCommand>)(r =>
            {
                var p = new byte[r.Next(0, 50)];
                r.NextBytes(p);
                return new RawFinsCommand(0x2801, p);
            }),
        };
    }

    [Theory]
    [MemberData(nameof(Generators))]
    public void Command_survives_encode_frame_parse(string kind, object generator)
    {
        // The generator arrives as object: the test method is public, the protocol types are internal.
        var generate = (Func<Random, FinsCommand>)generator;
        var random = new Random(kind.GetHashCode(StringComparison.Ordinal) & 0x7FFF ^ 0x5EED);
        for (int i = 0; i < Iterations; i++)
        {
            FinsCommand command = generate(random);
            FinsHeader header = Header(random);
            int unit = random.Next(32);

            byte[] frame = FinsMessage.EncodeCommandFrame(unit, header, command);
            frame.Length.Should().BeLessThanOrEqualTo(FinsMessage.MaxFrameLength);
            FrameParser.ParseFirst(frame).IsFinal.Should().BeTrue();

            FinsCommandMessage message = FinsMessage.ParseCommandFrame(frame);
            message.Unit.Should().Be(unit);
            message.Header.Should().Be(header);
            message.CommandCode.Should().Be(command.CommandCode);

            FinsCommand parsed = message.ToCommand();
            parsed.Should().BeOfType(command.GetType());
            parsed.Should().Be(command);
            parsed.Should().BeEquivalentTo(command, o => o.RespectingRuntimeTypes());
        }
    }

    [Fact]
    public void Typed_fields_survive_a_round_trip_of_a_clock_write()
    {
        var command = new ClockWriteCommand(new DateTime(1999, 12, 31, 23, 59, 58), includeSecond: true, DayOfWeek.Sunday);
        var parsed = (ClockWriteCommand)FinsMessage.ParseCommandFrame(FinsMessage.EncodeCommandFrame(0, FinsHeader.Direct(), command)).ToCommand();
        parsed.Time.Should().Be(new DateTime(1999, 12, 31, 23, 59, 58));
        parsed.DayOfWeek.Should().Be(DayOfWeek.Sunday, "the day of week is sent as given even when it disagrees with the date");
    }

    [Fact]
    public void Writer_output_without_FCS_is_the_unframed_message()
    {
        var command = new MemoryAreaReadCommand(new FinsMemoryAddress(0x82, 1), 1);
        var buffer = new byte[FinsMessage.GetCommandLength(FinsHeader.Direct(), command)];
        int n = FinsMessage.WriteCommand(buffer, 0, FinsHeader.Direct(), command);
        n.Should().Be(buffer.Length);
        var framed = new byte[n + FrameWriter.FinalOverhead];
        FrameWriter.WriteFrame(buffer, final: true, framed);
        framed.Should().Equal(FinsMessage.EncodeCommandFrame(0, FinsHeader.Direct(), command));
    }
}
