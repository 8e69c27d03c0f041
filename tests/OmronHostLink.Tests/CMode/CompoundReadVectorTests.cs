using System.Text;
using FluentAssertions;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Protocol;
using Xunit;

namespace OmronHostLink.Tests.CMode;

/// <summary>
/// QQ, the compound read, against the frames of the manuals (<see cref="CompoundReadFrames"/>): written, parsed, read
/// and answered by the simulator as they show.
/// </summary>
public class CompoundReadVectorTests
{
    private const string RegisterFrame = CompoundReadFrames.Register;
    private const string RegisterAnswer = CompoundReadFrames.RegisterAnswer;
    private const string ReadFrame = CompoundReadFrames.Read;
    private const string ReadAnswer = CompoundReadFrames.ReadAnswer;
    private const string NothingRegistered = CompoundReadFrames.NothingRegistered;

    private static readonly CompoundItem[] Items =
    [
        CompoundItem.ForBit(CompoundArea.Cio, 1, 5),
        CompoundItem.ForWord(CompoundArea.Dm, 1000),
        CompoundItem.ForWord(CompoundArea.Timer, 5),
    ];

    private static string Framed(CModeCommand command)
    {
        byte[] message = command.ToMessage(0);
        var frame = new byte[message.Length + FrameWriter.FinalOverhead];
        int n = FrameWriter.WriteFrame(message, final: true, frame);
        return Encoding.ASCII.GetString(frame, 0, n);
    }

    private static string Framed(SimResponse response) => Encoding.ASCII.GetString(response.ToFrames().Single());

    [Fact]
    public void The_commands_are_written_as_the_manuals_show()
    {
        Framed(new CompoundRegisterCommand(Items)).Should().Be(RegisterFrame);
        Framed(CompoundCommands.ReadCommand).Should().Be(ReadFrame);
        new CompoundRegisterCommand(Items).Effect.Should().Be(CommandEffect.Idempotent);
        CompoundCommands.ReadCommand.Effect.Should().Be(CommandEffect.ReadOnly);
    }

    [Fact]
    public void The_parser_reads_the_registration_as_the_manuals_show()
    {
        var command = (CompoundRegisterCommand)CModeCommand.Parse("QQ"u8, Encoding.ASCII.GetBytes(RegisterFrame[5..^4]));
        command.Items.Should().Equal(Items);
        command.Items.Sum(i => i.Weight).Should().Be(4); // the timer PV counts as two items

        // A comma just before the FCS is taken; a missing item between two commas is a format error (14); an area the
        // manuals do not list is an entry number data error (15).
        ((CompoundRegisterCommand)CModeCommand.Parse("QQ"u8, "MRDM  1000CH,"u8)).Items.Should().ContainSingle();
        Refusal("MRDM  1000CH,,CIO 000105").Should().Be(EndCode.FormatError);
        Refusal("MRXX  1000CH").Should().Be(EndCode.EntryNumberDataError);
        Refusal("MRCIO 000116").Should().Be(EndCode.EntryNumberDataError);
        Refusal("IRX").Should().Be(EndCode.FormatError);
    }

    [Fact]
    public void The_answer_is_read_in_registration_order()
    {
        var values = new ushort[3];
        var flags = new ushort[3];
        CompoundCommands.ReadData(Encoding.ASCII.GetBytes(ReadAnswer[9..^4]), Items, values, flags);
        values.Should().Equal(1, 0x1234, 0x0042);
        flags[2].Should().Be(0);
    }

    [Theory]
    [InlineData("1,1234,0004")] // short
    [InlineData("1,1234,00042,")] // long
    [InlineData("1;1234,00042")] // wrong break
    [InlineData("2,1234,00042")] // a bit is 0 or 1
    [InlineData("1,12G4,00042")] // a word is hex
    public void An_answer_of_another_shape_is_a_frame_error_never_values(string data)
    {
        FluentActions.Invoking(() => CompoundCommands.ReadData(Encoding.ASCII.GetBytes(data), Items, new ushort[3]))
            .Should().Throw<HostLinkFrameException>();
    }

    [Fact]
    public void The_simulator_answers_as_the_manuals_show_and_19_before_any_registration()
    {
        var plc = new VirtualPlc();
        plc.SetBit(PlcArea.Cio, 1, 5, true);
        plc.WriteWord(PlcArea.Dm, 1000, 0x1234);
        plc.WriteWord(PlcArea.Timer, 5, 0x0042);
        var responder = new HostLinkResponder(plc);

        Framed(responder.Respond(Encoding.ASCII.GetBytes(ReadFrame[..^4]))!).Should().Be(NothingRegistered);
        Framed(responder.Respond(Encoding.ASCII.GetBytes(RegisterFrame[..^4]))!).Should().Be(RegisterAnswer);
        Framed(responder.Respond(Encoding.ASCII.GetBytes(ReadFrame[..^4]))!).Should().Be(ReadAnswer);

        // One registration per unit, lost when the PLC restarts.
        plc.Restart();
        Framed(responder.Respond(Encoding.ASCII.GetBytes(ReadFrame[..^4]))!).Should().Be(NothingRegistered);
    }

    private static EndCode Refusal(string text)
        => FluentActions.Invoking(() => CModeCommand.Parse("QQ"u8, Encoding.ASCII.GetBytes(text)))
            .Should().Throw<CModeCommandRejectedException>().Which.EndCode;
}
