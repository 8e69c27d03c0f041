using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>The gateway's configuration reads a duration as the core's <see cref="Duration"/> grammar does, or refuses it with its words.</summary>
public sealed class GatewayDurationTests
{
    [Theory]
    [MemberData(nameof(DurationTexts.All), MemberType = typeof(DurationTexts))]
    public async Task The_gateway_configuration_reads_durations_as_the_core_grammar_does(string text, long? ticks)
    {
        using IHost host = TestGatewayHost.CreateBuilder(new Dictionary<string, string?>
        {
            ["HostLink:Links:plc:Tcp"] = "127.0.0.1:9",
            ["HostLink:Links:plc:Groups:g:Address"] = "D0",
            ["HostLink:Links:plc:Groups:g:Interval"] = text,
        }).Build();

        if (ticks is { } t)
        {
            host.Services.GetRequiredService<IOptions<GatewayOptions>>().Value.Links["plc"].Groups["g"].Interval
                .Should().Be(TimeSpan.FromTicks(t));
        }
        else
        {
            Exception? failure = await Record.ExceptionAsync(() => host.StartAsync());
            failure.Should().BeOfType<OptionsValidationException>()
                .Which.Failures.Should().Contain($"HostLink:Links:plc:Groups:g:Interval {DurationTexts.Refusal(text)}.");
        }
    }
}
