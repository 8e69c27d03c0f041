using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Gateway.Tests.Sparkplug;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>What the gateway says is what is wrong: no reason that points elsewhere, no setting ignored without a word.</summary>
public sealed class GatewayReasonTests
{
    [Fact]
    public async Task HostLinkCompatibleMode_under_FINS_is_refused_naming_the_key()
    {
        IReadOnlyList<string> failures = await FailuresAsync(new()
        {
            ["HostLink:Links:plc:Tcp"] = "127.0.0.1:9",
            ["HostLink:Links:plc:CommandSet"] = "Fins",
            ["HostLink:Links:plc:HostLinkCompatibleMode"] = "ModeA",
            ["HostLink:Links:plc:Groups:g:Address"] = "D0",
        });

        failures.Should().Equal("HostLink:Links:plc:HostLinkCompatibleMode ModeA checks how a unit frames C-mode answers; with CommandSet Fins it would be ignored. Remove it, or set CommandSet CMode.");
    }

    [Fact]
    public async Task A_link_without_groups_is_named_as_such_not_as_no_link()
    {
        IReadOnlyList<string> failures = await FailuresAsync(new() { ["HostLink:Links:plc:Tcp"] = "127.0.0.1:9" });

        failures.Should().Equal("HostLink:Links:plc:Groups: the link has no poll group.");
    }

    [Fact]
    public async Task A_url_for_a_link_endpoint_is_called_a_url()
    {
        IReadOnlyList<string> failures = await FailuresAsync(new()
        {
            ["HostLink:Links:plc:Tcp"] = "tcp://127.0.0.1:27600",
            ["HostLink:Links:plc:Groups:g:Address"] = "D0",
        });

        failures.Should().ContainSingle().Which.Should().StartWith("HostLink:Links:plc:Tcp: 'tcp://127.0.0.1:27600' is a URL; write host:port without a scheme")
            .And.NotContain("IPv6");
    }

    [Fact]
    public async Task An_unreachable_broker_of_the_edge_node_is_named_in_plain_words()
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(9, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        config["Sparkplug:Host"] = "127.0.0.1";
        config["Sparkplug:Port"] = "1"; // closed on 127.0.0.1
        config["Sparkplug:GroupId"] = SparkplugEndToEndTests.Group;
        config["Sparkplug:EdgeNodeId"] = SparkplugEndToEndTests.Node;
        MqttGatewayConfig.Group(config, "g", "D100");
        var logs = new CapturingLoggerProvider();
        using IHost host = MqttGatewayConfig.Build(config, logs);
        await host.StartAsync();
        try
        {
            await MqttGatewayConfig.Eventually(() => logs.WithEvent(1302).Count > 0, "the broker is reported unreachable", logs);
        }
        finally
        {
            await host.StopAsync();
        }

        logs.WithEvent(1302)[0].Message.Should().StartWith("Sparkplug: broker 127.0.0.1:1 unreachable (Connection refused);")
            .And.NotContain("Unspecified");
    }

    private static async Task<IReadOnlyList<string>> FailuresAsync(Dictionary<string, string?> config)
    {
        using IHost host = TestGatewayHost.Build(config, new CapturingLoggerProvider(), TimeSpan.FromSeconds(5));
        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());
        return error.Should().BeOfType<OptionsValidationException>().Subject.Failures.ToList();
    }
}
