using System.Text;
using FluentAssertions;
using OmronHostLink.Cli;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Protocol;
using Xunit;

namespace OmronHostLink.Tests.CMode;

/// <summary>
/// QQ frames written by hand from the command and response formats of the manuals (the FCS computed separately, not
/// with this library): W342 4-3-35 REGISTER I/O MEMORY – QQMR and 4-3-36 READ I/O MEMORY – QQIR (p146–147 of the
/// 07-2009 edition; end codes p105: QQMR 00 13 14 15 18 21 A3–A8, QQIR 00 13 14 18 19); C200HS operation manual 11-3-33
/// COMPOUND COMMAND – QQ (p428–429); CPM1 programming manual 4-5-30 (p302); CQM1H programming manual 6-5-34 (p470–471).
/// Item: read area (4 characters, spaces filled: <c>CIO </c>, <c>DM  </c>, <c>TIM </c>), word (4 decimal digits), data
/// format (bit <c>00</c>–<c>15</c> or <c>CH</c>), items separated by <c>,</c>. QQIR answer: the items in registration
/// order, separated by <c>,</c>: a bit as 0/1, a word as four hex digits, a timer/counter PV as its Completion Flag followed
/// by the PV. The manuals show formats only; these frames instantiate them.
/// </summary>
public class CompoundReadVectorTests
{
    // CIO 1.05 (bit), DM 1000 (word), TIM 5 (CH: Completion Flag and PV).
    private const string RegisterFrame = "@00QQMRCIO 000105,DM  1000CH,TIM 0005CH43*\r";
    private const string RegisterAnswer = "@00QQMR005F*\r";
    private const string ReadFrame = "@00QQIR5B*\r";

    // CIO 1.05 on, DM 1000 = 1234 hex, TIM 5 flag off with PV 0042.
    private const string ReadAnswer = "@00QQIR001,1234,0004258*\r";

    // W342 end code 19 (not executable): QQIR with nothing registered.
    private const string NothingRegistered = "@00QQIR1953*\r";

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

    [Fact]
    public void Explain_decodes_both_commands_and_both_answers()
    {
        FrameExplanation register = FrameExplainer.Explain(RegisterFrame, null);
        register.Name.Should().Be("REGISTER I/O MEMORY (QQMR)");
        register.IsResponse.Should().BeFalse();
        register.Fields["items"].Should().BeEquivalentTo(new[] { "CIO 000105", "DM  1000CH", "TIM 0005CH" });

        FrameExplanation answer = FrameExplainer.Explain(ReadAnswer, null);
        answer.Name.Should().Be("READ I/O MEMORY (QQIR)");
        answer.IsResponse.Should().BeTrue();
        answer.EndCode.Should().Be("00");
        answer.Fields["items"].Should().BeEquivalentTo(new[] { "1", "1234", "00042" });
        answer.Problems.Should().BeEmpty();

        FrameExplanation refused = FrameExplainer.Explain(NothingRegistered, true);
        refused.EndCode.Should().Be("19");
        refused.Problems.Should().BeEmpty();

        FrameExplainer.Explain(RegisterAnswer, true).EndCode.Should().Be("00");
    }

    private static EndCode Refusal(string text)
        => FluentActions.Invoking(() => CModeCommand.Parse("QQ"u8, Encoding.ASCII.GetBytes(text)))
            .Should().Throw<CModeCommandRejectedException>().Which.EndCode;
}
