using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;

namespace OmronHostLink.DependencyInjection.Tests;

/// <summary>
/// A client's configuration and <c>AddHostLinkClient(..., Action)</c> read each text of <see cref="DurationTexts"/> as
/// the core's grammar does: the same time, or the same refusal at start.
/// </summary>
public sealed class DurationConfigurationTests
{
    [Theory]
    [MemberData(nameof(DurationTexts.All), MemberType = typeof(DurationTexts))]
    public async Task DI_configuration_reads_it_the_same(string text, long? ticks)
    {
        string json = $$"""{ "HostLink": { "Clients": { "line1": { "Tcp": { "Host": "127.0.0.1", "Port": 9, "ConnectTimeout": "{{text}}" } } } } }""";
        void Register(IServiceCollection services, IConfiguration configuration) => services.AddHostLinkClients(configuration.GetSection("HostLink:Clients"));

        if (ticks is { } t)
        {
            await using JsonHost host = JsonHost.Build(json, Register);
            await host.Host.StartAsync();
            host.Services.GetRequiredService<IOptionsMonitor<HostLinkClientSettings>>().Get("line1").Tcp.ConnectTimeout
                .Should().Be(TimeSpan.FromTicks(t));
        }
        else
        {
            IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(json, Register);
            failures.Should().Equal($"HostLink:Clients:line1:Tcp:ConnectTimeout: {DurationTexts.Refusal(text)}");
        }
    }

    [Theory]
    [MemberData(nameof(DurationTexts.All), MemberType = typeof(DurationTexts))]
    public async Task AddHostLinkClient_with_an_action_reads_it_the_same(string text, long? ticks)
    {
        await using JsonHost host = JsonHost.Build("{}", (services, _) => services.AddHostLinkClient("line1", o =>
        {
            o.Tcp.Host = "127.0.0.1";
            o.Tcp.Port = 9;
            o.Tcp.ConnectTimeout = Duration.Parse(text);
        }));
        Exception? failure = await Record.ExceptionAsync(() => host.Host.StartAsync());

        if (ticks is { } t)
        {
            failure.Should().BeNull();
            host.Services.GetRequiredService<IOptionsMonitor<HostLinkClientSettings>>().Get("line1").Tcp.ConnectTimeout
                .Should().Be(TimeSpan.FromTicks(t));
        }
        else
        {
            failure.Should().BeOfType<FormatException>().Which.Message.Should().Be(DurationTexts.Refusal(text));
        }
    }
}
