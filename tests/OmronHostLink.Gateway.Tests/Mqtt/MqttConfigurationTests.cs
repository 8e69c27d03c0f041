using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using MQTTnet;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>The <c>Mqtt</c> section: opt-in, and checked at start naming the key.</summary>
public sealed class MqttConfigurationTests
{
    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public async Task Without_an_enabled_mqtt_section_no_mqtt_client_is_made_and_the_worker_only_logs(bool disabledSection)
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [11]);
        await using var simulator = new TcpSimulatorHost(plc);
        await simulator.StartAsync();
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.EndPoint.Port, broker: null);
        foreach (string key in config.Keys.Where(k => k.StartsWith("Mqtt:", StringComparison.Ordinal)).ToList())
        {
            config.Remove(key);
        }

        if (disabledSection)
        {
            config["Mqtt:Enabled"] = "false";
            config["Mqtt:Host"] = "127.0.0.1";
        }

        MqttGatewayConfig.Group(config, "level", "D100", intervalMs: 50);
        var logs = new CapturingLoggerProvider();
        using IHost host = MqttGatewayConfig.Build(config, logs);
        await host.StartAsync();
        try
        {
            await MqttGatewayConfig.Eventually(() => logs.WithEvent(GatewayLog.Events.Values).Count > 0, "the value is logged", logs);
        }
        finally
        {
            await host.StopAsync();
        }

        host.Services.GetService<MqttClientFactory>().Should().BeNull("no MQTT client can be made");
        host.Services.GetService<MqttGateway>().Should().BeNull();
        host.Services.GetServices<ITagOutput>().Should().ContainSingle("the links report to no output but the statistics (metrics)")
            .Which.Should().BeOfType<OmronHostLink.Gateway.Statistics.LinkStatistics>();
        host.Services.GetServices<IHostedService>().Should().NotContain(s => s is MqttGateway);
        logs.Entries.Should().NotContain(e => e.Category.StartsWith("OmronHostLink.Gateway.Mqtt", StringComparison.Ordinal));
        logs.WithEvent(GatewayLog.Events.Values).First().Message.Should().Be("plc/level: unit 0 D100 = 11");
    }

    private static string NotPem => Path.Combine(AppContext.BaseDirectory, "OmronHostLink.Gateway.Tests.dll");

    public static TheoryData<string, string> BadSettings => new()
    {
        { "Mqtt:Host=", "Mqtt:Host is empty" },
        { "Mqtt:Host=broker:1883", "Mqtt:Host 'broker:1883' is not a host name or address" },
        { "Mqtt:Port=70000", "Mqtt:Port must be 1-65535; it is 70000" },
        { "Mqtt:Port=0", "Mqtt:Port must be 1-65535; it is 0" },
        { "Mqtt:QoS=3", "Mqtt:QoS must be 0, 1 or 2; it is 3" },
        { "Mqtt:TopicPrefix=plant/+", "Mqtt:TopicPrefix 'plant/+': a level holds '+'" },
        { "Mqtt:TopicPrefix=plant/#", "Mqtt:TopicPrefix 'plant/#': a level holds '#'" },
        { "Mqtt:TopicPrefix=/plant", "Mqtt:TopicPrefix '/plant': a level is empty" },
        { "Mqtt:TopicPrefix=$SYS/x", "Mqtt:TopicPrefix '$SYS/x' starts with '$'" },
        { "Mqtt:ClientId=worker/1", "Mqtt:ClientId 'worker/1' names the worker's status topic" },
        { "Mqtt:Password=secret", "Mqtt:Password is set without Mqtt:Username" },
        { "Mqtt:QueueCapacity=0", "Mqtt:QueueCapacity must be 1-10000000; it is 0" },
        { "Mqtt:KeepAlive=1.5s", "Mqtt:KeepAlive is sent in whole seconds; 00:00:01.5000000 is not" },
        { "Mqtt:Timeout=00:00:00", "Mqtt:Timeout must be more than 0" },
        { "Mqtt:Reconnect:Max=00:00:00.050", "Mqtt:Reconnect:Max (00:00:00.0500000) must be at least Reconnect:Initial" },
        { "Mqtt:Tls:Enabled=true;Mqtt:Tls:CaFile=/nonexistent/ca.pem", "Mqtt:Tls:CaFile '/nonexistent/ca.pem' does not exist" },
        { $"Mqtt:Tls:Enabled=true;Mqtt:Tls:CaFile={NotPem}", $"Mqtt:Tls:CaFile '{NotPem}' cannot be read as PEM certificates" },
        { "Mqtt:Tls:Enabled=true;Mqtt:Tls:CaFile=/nonexistent/ca.pem;Mqtt:Tls:AllowUntrustedCertificates=true", "Mqtt:Tls: set either CaFile or AllowUntrustedCertificates, not both" },
        { "Mqtt:Tls:AllowUntrustedCertificates=true", "Mqtt:Tls:Enabled is false but AllowUntrustedCertificates is set" },
        { "Mqtt:Writes:ReplyPrefixes:0=test", "Mqtt:Writes:ReplyPrefixes:0 'test' overlaps Mqtt:TopicPrefix 'test'" },
        { "Mqtt:Writes:ReplyPrefixes:0=test/replies", "Mqtt:Writes:ReplyPrefixes:0 'test/replies' overlaps Mqtt:TopicPrefix 'test'" },
        { "Mqtt:Writes:ReplyPrefixes:0=replies/+", "Mqtt:Writes:ReplyPrefixes:0 'replies/+' is not a topic prefix: a level holds '+'" },
        { "Mqtt:Writes:ReplyPrefixes:0=replies/", "Mqtt:Writes:ReplyPrefixes:0 'replies/' is not a topic prefix: a level is empty" },
        { "Mqtt:Writes:ReplyPrefixes:0=scada/replies", "" },
        { "HostLink:Links:plc:Groups:g:Writable=true", "" }, // a writable int16 in DM is fine
        { "HostLink:Links:plc:Groups:flag:Writable=true", "HostLink:Links:plc:Groups:flag:Writable: T5 is a timer/counter completion flag" },
        { "HostLink:Links:plc:Groups:bits:Writable=true", "HostLink:Links:plc:Groups:bits:Writable: a writable bit group must have Count 1" },
        { "HostLink:Links:plc:Groups:a+b:Address=D1", "HostLink:Links:plc:Groups:a+b: the group's name is a topic level for MQTT and holds '+'" },
    };

    [Theory]
    [MemberData(nameof(BadSettings))]
    public async Task Invalid_mqtt_configuration_fails_at_start_naming_the_key(string settings, string expected)
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(9, broker: null);
        MqttGatewayConfig.Group(config, "g", "D100");
        MqttGatewayConfig.Group(config, "flag", "T5", "bit");
        MqttGatewayConfig.Group(config, "bits", "CIO10.00", "bit", count: 4);
        foreach (string setting in settings.Split(';'))
        {
            string[] pair = setting.Split('=', 2);
            config[pair[0]] = pair[1];
        }

        var logs = new CapturingLoggerProvider();
        using IHost host = MqttGatewayConfig.Build(config, logs);

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        if (expected.Length == 0)
        {
            error.Should().BeNull();
            await host.StopAsync();
            return;
        }

        error.Should().NotBeNull();
        Messages(error!).Should().Contain(m => m.Contains(expected, StringComparison.Ordinal), $"the message names the key ({string.Join(" | ", Messages(error!))})");
        logs.WithEvent(GatewayLog.Events.LinkStarted).Should().BeEmpty("nothing starts");
    }

    [Fact]
    public async Task A_link_named_status_is_refused_with_mqtt_on()
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(9, broker: null);
        foreach (string key in config.Keys.Where(k => k.StartsWith("HostLink:Links:plc:", StringComparison.Ordinal)).ToList())
        {
            config["HostLink:Links:status:" + key.Substring("HostLink:Links:plc:".Length)] = config[key];
            config.Remove(key);
        }

        config["HostLink:Links:status:Groups:g:Address"] = "D100";
        using IHost host = MqttGatewayConfig.Build(config, new CapturingLoggerProvider());

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        Messages(error!).Should().Contain(m => m.Contains("HostLink:Links:status: a link cannot be named 'status' with MQTT on", StringComparison.Ordinal));
    }

    [Fact]
    public async Task An_unreachable_broker_is_named_once_in_plain_words()
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(9, broker: null); // Mqtt:Port 1: closed on 127.0.0.1
        MqttGatewayConfig.Group(config, "g", "D100");
        var logs = new CapturingLoggerProvider();
        using IHost host = MqttGatewayConfig.Build(config, logs);
        await host.StartAsync();
        try
        {
            await MqttGatewayConfig.Eventually(() => logs.WithEvent(MqttLog.Events.Unreachable).Count > 0, "the broker is reported unreachable", logs);
        }
        finally
        {
            await host.StopAsync();
        }

        logs.WithEvent(MqttLog.Events.Unreachable)[0].Message.Should().StartWith("MQTT: broker 127.0.0.1:1 not reachable (Connection refused);")
            .And.NotContain("Unspecified");
    }

    private static IEnumerable<string> Messages(Exception e) => ExceptionMessages.Of(e);
}
