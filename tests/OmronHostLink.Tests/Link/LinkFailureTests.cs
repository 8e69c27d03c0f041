using OmronHostLink.Link;
using OmronHostLink.Protocol.Fins;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Link;

/// <summary>How the link tells failures apart: through what the exceptions share, not through the command set.</summary>
public sealed class LinkFailureTests
{
    // Frames from ../shared/hostlink/vectors.json: wdpy_wd_d9 answered by c_wd_resp_01 (not executable in RUN mode),
    // then roof_rd_d100_3 answered by c_rd_resp_3w.
    private const string WdD9 = "@00WD000900015B*\r";
    private const string WdRunModeAnswer = "@00WD0152*\r";
    private const string RdD100x3 = "@00RD0100000354*\r";
    private const string Rd3WordsResponse = "@00RD00000AFFFF80002F*\r";

    [Fact]
    public async Task An_end_code_answer_leaves_the_link_in_step_so_no_fence_precedes_the_next_request()
    {
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        var options = new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = InProcessLine.InMemoryAllowance };
        await using var client = HostLinkClient.ForStream(host, options);
        await using var plc = new ScriptedPlc(plcEnd, f => f switch
        {
            WdD9 => new Reply(WdRunModeAnswer),
            RdD100x3 => new Reply(Rd3WordsResponse),
            _ => null,
        });

        var e = await FluentActions.Awaiting(() => client.WriteWordAsync("D9", 1)).Should().ThrowAsync<EndCodeException>();
        e.Which.Should().BeOfType<HostLinkEndCodeException>().Which.EndCode.Should().Be(EndCode.NotExecutableInRunMode);

        (await client.ReadWordsAsync("D100", 3)).Should().Equal(0x000A, 0xFFFF, 0x8000);
        plc.Received.Should().Equal(new[] { WdD9, RdD100x3 }, "a complete answer, even an error one, leaves the line in step");
    }

    // docs/telemetry.md, error.type: an end code's name, end_code_XX for a code the manuals do not define, and fins_
    // with the response code without its flag bits (8401 = 0401 with the network-relay-error flag).
    [Fact]
    public void Each_end_code_exception_names_its_own_error_type()
    {
        ErrorTypes.Of(new HostLinkEndCodeException(EndCode.NotExecutableInRunMode, "WD", 0)).Should().Be("NotExecutableInRunMode");
        ErrorTypes.Of(new HostLinkEndCodeException((EndCode)0x99, "RD", 0)).Should().Be("end_code_99");
        ErrorTypes.Of(new FinsEndCodeException(new FinsEndCode(0x8401), 0x0101, 3)).Should().Be("fins_0401");
        new FinsEndCodeException(new FinsEndCode(0x1103), 0x0101, 3).Should().BeAssignableTo<EndCodeException>().Which.Unit.Should().Be(3);
    }
}
