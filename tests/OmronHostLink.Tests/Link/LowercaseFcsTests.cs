using OmronHostLink.Link;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Link;

/// <summary>
/// The link compares the FCS character for character: Omron writes it in upper case, so an answer whose FCS is right
/// only in lower case is damaged (a changed character), never a value. <c>explain</c> names that case "lowercase FCS".
/// </summary>
public sealed class LowercaseFcsTests
{
    [Fact]
    public async Task An_answer_whose_fcs_is_right_only_in_lower_case_is_refused_as_a_bad_fcs()
    {
        // roof_rd_d100_3 answered by c_rd_resp_3w with its FCS 2F written as 2f.
        const string Command = "@00RD0100000354*\r";
        const string Answer = "@00RD00000AFFFF80002f*\r";
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        await using var plc = new ScriptedPlc(plcEnd, f => f == Command ? new Reply(Answer) : null);
        await using var client = HostLinkClient.ForStream(host, new HostLinkClientOptions
        {
            LineTiming = new LineTiming(115200, 11),
            TurnaroundAllowance = Allowances.LosslessLine,
            ReadRetries = 0,
        });

        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkFrameException>();

        e.Which.Error.Should().Be(FrameError.BadFcs);
    }
}
