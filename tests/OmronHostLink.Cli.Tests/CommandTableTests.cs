using System.Text;
using FluentAssertions;
using OmronHostLink.Cli;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Protocol;
using Xunit;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// A command added as one row of a table, and nothing else, is parsed, executed by the simulator and explained: the
/// parser, the simulator's dispatcher, <c>explain</c> and its direction guess all look commands up in the table — the
/// C-mode table and the FINS table alike.
/// </summary>
public class CommandTableTests
{
    // A made-up command: ZZ + 4 decimal digits n; the PLC answers end code 00 and DM word n as 4 hex digits.
    private static readonly CModeCommandRow FakeRow = CreateFakeRow();

    private static readonly CModeCommandTable Table = CModeCommandTable.Standard.With(FakeRow);

    private static CModeCommandRow CreateFakeRow()
    {
        CModeCommandRow row = null!;
        row = new CModeCommandRow("ZZ", "FAKE DM WORD READ", CommandEffect.ReadOnly, CModeResponse.EndCodeLength + 4)
        {
            Parse = text =>
            {
                CModeCommandParser.ExpectLength(text, 4, "ZZ");
                if (!HexAscii.TryParseDecimal(text, out _))
                {
                    throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "ZZ takes a decimal word number.");
                }

                return new SimpleCommand(row, text);
            },
            Execute = static (command, plc, _) =>
            {
                HexAscii.TryParseDecimal(((SimpleCommand)command).Text, out int word);
                Span<byte> data = stackalloc byte[4];
                HexAscii.WriteWord(plc.ReadWord(PlcArea.Dm, word, 0), data);
                return CModeReply.Ok(EndCode.NormalCompletion, null, data);
            },
            DescribeCommand = static (command, fields) =>
            {
                HexAscii.TryParseDecimal(((SimpleCommand)command).Text, out int word);
                fields.Field("word", (long)word);
            },
            DescribeAnswer = static (data, fields) =>
            {
                var value = new ushort[1];
                CModeResponse.ReadWords(data, value);
                fields.Field("value", (long)value[0]);
            },
        };
        return row;
    }

    private static string Frame(string message)
    {
        var buffer = new byte[message.Length + FrameWriter.FinalOverhead];
        int n = FrameWriter.WriteFrame(Encoding.ASCII.GetBytes(message), final: true, buffer);
        return Encoding.ASCII.GetString(buffer, 0, n);
    }

    [Fact]
    public void The_parser_takes_the_row_and_refuses_what_the_row_refuses()
    {
        CModeCommand command = CModeCommandParser.Parse(Table, "ZZ"u8, "0100"u8);
        command.Row.Should().BeSameAs(FakeRow);
        command.Effect.Should().Be(CommandEffect.ReadOnly);
        command.Exchange.MaxAnswerText.Should().Be(6);
        command.ToString().Should().Be("ZZ0100");

        FluentActions.Invoking(() => CModeCommandParser.Parse(Table, "ZZ"u8, "01X0"u8))
            .Should().Throw<CModeCommandRejectedException>().Which.EndCode.Should().Be(EndCode.EntryNumberDataError);
        FluentActions.Invoking(() => CModeCommandParser.Parse(CModeCommandTable.Standard, "ZZ"u8, "0100"u8))
            .Should().Throw<CModeCommandRejectedException>().Which.EndCode.Should().Be(EndCode.UndefinedHeader);
    }

    [Fact]
    public void The_simulator_executes_the_row()
    {
        var plc = new VirtualPlc();
        plc.WriteWord(PlcArea.Dm, 100, 0xBEEF);

        SimResponse? answer = new HostLinkResponder(plc, Table).Respond("@00ZZ0100"u8);
        SimResponse? refused = new HostLinkResponder(plc, Table).Respond("@00ZZ01"u8);
        SimResponse? standard = new HostLinkResponder(plc).Respond("@00ZZ0100"u8);

        answer!.ToString().Should().Be("@00ZZ00BEEF");
        refused!.ToString().Should().Be("@00ZZ14");
        standard!.ToString().Should().Be("@00IC");
    }

    [Fact]
    public void Explain_names_and_decodes_the_row_both_ways()
    {
        FrameExplanation command = FrameExplainer.Explain(Frame("@00ZZ0100"), null, Table);
        command.Name.Should().Be("FAKE DM WORD READ");
        command.IsResponse.Should().BeFalse();
        command.Problems.Should().BeEmpty();
        command.Fields["word"].Should().Be(100L);

        // "@00ZZ00BEEF" is no ZZ command (6 characters of text), but it is a well-formed ZZ answer: told by its shape.
        FrameExplanation answer = FrameExplainer.Explain(Frame("@00ZZ00BEEF"), null, Table);
        answer.IsResponse.Should().BeTrue();
        answer.DirectionFrom.Should().Be(FrameExplanation.FromShape);
        answer.EndCode.Should().Be("00");
        answer.Fields["value"].Should().Be(0xBEEFL);

        FrameExplanation unknown = FrameExplainer.Explain(Frame("@00ZZ0100"), false, CModeCommandTable.Standard);
        unknown.Name.Should().BeNull();
        unknown.Fields["wouldAnswer"].Should().Be("IC");
    }

    // A made-up FINS command: 7F01 + a word number (2 bytes); the PLC answers DM word n (2 bytes).
    private static readonly FinsCommandRow FakeFinsRow = CreateFakeFinsRow();

    private static readonly FinsCommandTable FinsTable = FinsCommandTable.Standard.With(FakeFinsRow);

    private static FinsCommandRow CreateFakeFinsRow()
    {
        FinsCommandRow row = null!;
        row = new FinsCommandRow(0x7F01, "FAKE DM WORD READ", CommandEffect.ReadOnly, 2)
        {
            Parse = parameters =>
            {
                FinsCommand.CheckLength(0x7F01, parameters, 2, 2);
                return new SimpleFinsCommand(row, parameters);
            },
            Execute = static (command, plc) =>
            {
                int word = FinsBytes.ReadUInt16(((SimpleFinsCommand)command).Parameters, 0);
                var data = new byte[2];
                FinsBytes.WriteUInt16(data, 0, plc.ReadWord(PlcArea.Dm, word, 0));
                return FinsReply.Ok(data);
            },
            DescribeCommand = static (command, fields) => fields.Field("word", (long)FinsBytes.ReadUInt16(((SimpleFinsCommand)command).Parameters, 0)),
            DescribeAnswer = static (data, fields) => fields.Field("value", (long)FinsBytes.ReadUInt16(data, 0)),
        };
        return row;
    }

    private static string FinsFrame(FinsCommand command) => Encoding.ASCII.GetString(FinsMessage.EncodeCommandFrame(0, FinsHeader.Direct(), command));

    [Fact]
    public void The_fins_parser_takes_the_row_and_refuses_what_the_row_refuses()
    {
        FinsCommand command = FinsTable.Parse(0x7F01, [0x00, 0x64]);
        command.Row.Should().BeSameAs(FakeFinsRow);
        command.Effect.Should().Be(CommandEffect.ReadOnly);
        command.MaxResponseDataLength.Should().Be(2);

        FluentActions.Invoking(() => FinsTable.Parse(0x7F01, [0x00]))
            .Should().Throw<FinsFormatException>().Which.EndCode.Should().Be(new FinsEndCode(FinsEndCodes.CommandTooShort));
        FinsCommandTable.Standard.Parse(0x7F01, [0x00, 0x64]).Should().BeOfType<RawFinsCommand>();
    }

    [Fact]
    public void The_simulator_executes_the_fins_row()
    {
        var plc = new VirtualPlc();
        plc.WriteWord(PlcArea.Dm, 100, 0xBEEF);
        var fake = new SimpleFinsCommand(FakeFinsRow, [0x00, 0x64]);
        byte[] frame = FinsMessage.EncodeCommandFrame(0, FinsHeader.Direct(), fake);
        string message = Encoding.ASCII.GetString(frame, 0, frame.Length - FrameWriter.FinalOverhead);

        SimResponse? answer = new HostLinkResponder(plc, CModeCommandTable.Standard, FinsTable).Respond(Encoding.ASCII.GetBytes(message));
        SimResponse? standard = new HostLinkResponder(plc).Respond(Encoding.ASCII.GetBytes(message));

        FinsResponse read = FinsResponse.Parse(answer!.Message.AsSpan(CModeCommand.PrefixLength), 0);
        read.EndCode.IsSuccess.Should().BeTrue();
        FinsBytes.ReadUInt16(read.Data.Span, 0).Should().Be(0xBEEF);
        FinsResponse.Parse(standard!.Message.AsSpan(CModeCommand.PrefixLength), 0).EndCode.Raw.Should().Be(FinsEndCodes.UndefinedCommand);
    }

    [Fact]
    public void Explain_names_and_decodes_the_fins_row_both_ways()
    {
        var fake = new SimpleFinsCommand(FakeFinsRow, [0x00, 0x64]);
        FrameExplanation command = FrameExplainer.Explain(FinsFrame(fake), false, CModeCommandTable.Standard, FinsTable);
        command.Name.Should().Be("FINS 7F01 FAKE DM WORD READ");
        command.Problems.Should().BeEmpty();
        command.Fields["word"].Should().Be(100L);

        byte[] response = FinsMessage.EncodeResponseFrame(0, FinsHeader.Direct(), 0x7F01, new FinsEndCode(FinsEndCodes.NormalCompletion), [0xBE, 0xEF]);
        FrameExplanation answer = FrameExplainer.Explain(Encoding.ASCII.GetString(response), true, CModeCommandTable.Standard, FinsTable);
        answer.Problems.Should().BeEmpty();
        answer.Fields["value"].Should().Be(0xBEEFL);

        FrameExplanation unknown = FrameExplainer.Explain(FinsFrame(fake), false, CModeCommandTable.Standard);
        unknown.Name.Should().Be("FINS 7F01");
        unknown.Fields.Should().NotContainKey("word");
    }
}
