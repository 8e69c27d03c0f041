using System.Text;
using FluentAssertions;
using OmronHostLink.Cli;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Protocol;
using Xunit;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// A command added as one row of a table, and nothing else, is parsed, executed by the simulator and explained: the
/// parser, the simulator's dispatcher, <c>explain</c> and its direction guess all look commands up in the table.
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
}
