namespace OmronHostLink.Cli.Tests;

/// <summary><c>explain</c> decodes QQ, the compound read, from the frames of the manuals (<see cref="CompoundReadFrames"/>).</summary>
public sealed class CliExplainCompoundReadTests
{
    [Fact]
    public void Explain_decodes_both_commands_and_both_answers()
    {
        FrameExplanation register = FrameExplainer.Explain(CompoundReadFrames.Register, null);
        register.Name.Should().Be("REGISTER I/O MEMORY (QQMR)");
        register.IsResponse.Should().BeFalse();
        register.Fields["items"].Should().BeEquivalentTo(new[] { "CIO 000105", "DM  1000CH", "TIM 0005CH" });

        FrameExplanation answer = FrameExplainer.Explain(CompoundReadFrames.ReadAnswer, null);
        answer.Name.Should().Be("READ I/O MEMORY (QQIR)");
        answer.IsResponse.Should().BeTrue();
        answer.EndCode.Should().Be("00");
        answer.Fields["items"].Should().BeEquivalentTo(new[] { "1", "1234", "00042" });
        answer.Problems.Should().BeEmpty();

        FrameExplanation refused = FrameExplainer.Explain(CompoundReadFrames.NothingRegistered, true);
        refused.EndCode.Should().Be("19");
        refused.Problems.Should().BeEmpty();

        FrameExplainer.Explain(CompoundReadFrames.RegisterAnswer, true).EndCode.Should().Be("00");
    }
}
