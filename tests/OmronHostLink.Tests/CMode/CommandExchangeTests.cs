using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Tests.CMode;

/// <summary>What each C-mode command says about its own exchange: the longest answer, echo confusion, what a repeat does.</summary>
public sealed class CommandExchangeTests
{
    [Fact]
    public void Answer_sizes_come_from_the_answer_formats()
    {
        // Omron W342 section 4: MS answers end code + status (4) + FAL/FALS message (16); MF end code + 2 error words;
        // MM end code + model code; SC and writes an end code alone; RD end code + 4 digits a word; RG 1 digit a flag.
        CModeCommands.StatusReadCommand.Exchange.MaxAnswerText.Should().Be(2 + 4 + 16);
        new ErrorReadCommand(clear: false).Exchange.MaxAnswerText.Should().Be(2 + 8);
        CModeCommands.ModelReadCommand.Exchange.MaxAnswerText.Should().Be(2 + 2);
        new StatusChangeCommand(PlcMode.Run).Exchange.MaxAnswerText.Should().Be(2);
        new AreaWriteCommand(CModeArea.Dm, 0, new ushort[] { 1, 2 }).Exchange.MaxAnswerText.Should().Be(2);
        new AreaReadCommand(CModeArea.Dm, 0, 30).Exchange.MaxAnswerText.Should().Be(2 + 120);
        new AreaReadCommand(CModeArea.TimerCounterStatus, 5, 3).Exchange.MaxAnswerText.Should().Be(2 + 3);
        CModeCommands.AbortCommand.Exchange.ExpectsAnswer.Should().BeFalse();
    }

    [Fact]
    public void The_hot_path_read_shape_equals_the_command_object_shape()
    {
        foreach (CModeArea area in new[] { CModeArea.Dm, CModeArea.Em, CModeArea.TimerCounterStatus, CModeArea.Cio })
        {
            ExchangeShape fromCommand = new AreaReadCommand(area, 0, 40).Exchange;
            ExchangeShape hot = AreaReadCommand.GetExchange(area, 40);
            hot.Should().BeEquivalentTo(fromCommand, area.ToString());
        }
    }

    [Fact]
    public void An_answer_can_equal_the_command_only_for_TS_and_two_character_texts()
    {
        new TestCommand("ABC").Exchange.AnswerCanEqualCommand.Should().BeTrue("TS is answered with its own characters");
        new StatusChangeCommand(PlcMode.Program).Exchange.AnswerCanEqualCommand.Should().BeTrue("@00SC00 is also the answer 'SC, end code 00'");
        new ErrorReadCommand(clear: true).Exchange.AnswerCanEqualCommand.Should().BeTrue("@00MF01 is also the answer 'MF, end code 01'");
        CModeCommands.StatusReadCommand.Exchange.AnswerCanEqualCommand.Should().BeFalse();
        new AreaReadCommand(CModeArea.Dm, 100, 3).Exchange.AnswerCanEqualCommand.Should().BeFalse();
    }

    [Fact]
    public void Only_a_long_answer_may_span_frames()
    {
        new AreaReadCommand(CModeArea.Dm, 0, 30).Exchange.AnswerMaySpanFrames.Should().BeFalse("9 + 122 characters fit the first frame");
        new AreaReadCommand(CModeArea.Dm, 0, 31).Exchange.AnswerMaySpanFrames.Should().BeTrue();
        new AreaReadCommand(CModeArea.Dm, 0, 31).Exchange.MaxFirstAnswerFrame.Should().Be(FrameWriter.MaxFirstFrameLength);
    }

    [Fact]
    public void Repeating_is_decided_by_what_the_command_does()
    {
        CModeCommands.StatusReadCommand.Effect.Should().Be(CommandEffect.ReadOnly);
        new AreaReadCommand(CModeArea.Dm, 0, 1).Effect.Should().Be(CommandEffect.ReadOnly);
        new ErrorReadCommand(clear: false).Effect.Should().Be(CommandEffect.ReadOnly);
        new ErrorReadCommand(clear: true).Effect.Should().Be(CommandEffect.NotRepeatable);
        new AreaWriteCommand(CModeArea.Dm, 0, new ushort[] { 1 }).Effect.Should().Be(CommandEffect.Idempotent);
        new StatusChangeCommand(PlcMode.Run).Effect.Should().Be(CommandEffect.NotRepeatable);
        CModeCommands.AbortCommand.Effect.Should().Be(CommandEffect.NotRepeatable);
    }
}
