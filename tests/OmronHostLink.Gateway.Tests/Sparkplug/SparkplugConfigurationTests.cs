using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Sparkplug;
using OmronHostLink.Gateway.Tests.Mqtt;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>The <c>Sparkplug</c> section is checked at start like every other, each problem naming its key.</summary>
public sealed class SparkplugConfigurationTests
{
    public static TheoryData<string, string> BadSettings => new()
    {
        { "Sparkplug:GroupId=", "Sparkplug:GroupId '' cannot be a Sparkplug id: it is empty" },
        { "Sparkplug:GroupId=plant/1", "Sparkplug:GroupId 'plant/1' cannot be a Sparkplug id: it contains '/'" },
        { "Sparkplug:EdgeNodeId=gw+1", "Sparkplug:EdgeNodeId 'gw+1' cannot be a Sparkplug id: it contains '+'" },
        { "Sparkplug:Host=", "Sparkplug:Host is empty" },
        { "Sparkplug:Host=mqtt://broker", "Sparkplug:Host 'mqtt://broker' is not a host name or address" },
        { "Sparkplug:Port=0", "Sparkplug:Port must be 1-65535; it is 0" },
        { "Sparkplug:Password=secret", "Sparkplug:Password is set without Sparkplug:Username" },
        { "Sparkplug:KeepAlive=1.5s", "Sparkplug:KeepAlive is sent in whole seconds; 00:00:01.5000000 is not" },
        { "Sparkplug:KeepAlive=0s", "Sparkplug:KeepAlive must be 1s to 18:12:15 (whole seconds); it is 00:00:00" },
        { "Sparkplug:Timeout=0s", "Sparkplug:Timeout must be more than 0" },
        { "Sparkplug:Reconnect:Max=50ms", "Sparkplug:Reconnect:Max (00:00:00.0500000) must be at least Reconnect:Initial" },
        { "Sparkplug:Tls:AllowUntrustedCertificates=true", "Sparkplug:Tls:Enabled is false but AllowUntrustedCertificates is set" },
        { "Sparkplug:Tls:Enabled=true;Sparkplug:Tls:CaFile=/nonexistent/ca.pem", "Sparkplug:Tls:CaFile '/nonexistent/ca.pem' does not exist" },
        { "Sparkplug:EdgeNode=gw1", "Sparkplug:EdgeNode is not a setting here" },
        { "Sparkplug:PrimaryHostId=scada/1", "Sparkplug:PrimaryHostId 'scada/1' cannot be a Sparkplug id: it contains '/'" },
        { "Sparkplug:PrimaryHostId=scada#", "Sparkplug:PrimaryHostId 'scada#' cannot be a Sparkplug id: it contains '#'" },
        { "Sparkplug:PrimaryHostId= ", "Sparkplug:PrimaryHostId ' ' cannot be a Sparkplug id: it is empty" },
        { "Sparkplug:PrimaryHost=scada", "Sparkplug:PrimaryHost is not a setting here" },
        { "Sparkplug:PrimaryHostId=IamHost", "" },
        { "Sparkplug:Writes:Enabled=yes", "Sparkplug:Writes:Enabled 'yes' is not true or false" },
        { "HostLink:Links:plc:Groups:a#b:Address=D1", "HostLink:Links:plc:Groups:a#b: the group's name is a Sparkplug metric name and it contains '#'" },
        { "HostLink:Links:plc:Groups:flag:Writable=true", "HostLink:Links:plc:Groups:flag:Writable: T5 is a timer/counter completion flag" },
        { "HostLink:Links:plc:Demotion:After=-1", "HostLink:Links:plc:Demotion:After must be 0 (never demote) to 1000 polls; it is -1" },
        { "HostLink:Links:plc:Demotion:Period=0s", "HostLink:Links:plc:Demotion:Period must be more than 0 and at most 1 day" },
        { "HostLink:Links:plc:Demotion:Perod=5s", "HostLink:Links:plc:Demotion:Perod is not a setting here" },
        { "Sparkplug:Writes:Enabled=true", "" },
        { "Sparkplug:Servers:0:Host=127.0.0.1", "Sparkplug:Host is set beside Sparkplug:Servers; give either one broker (Sparkplug:Host, Sparkplug:Port) or the list" },
        { "Sparkplug:Host=;Sparkplug:Servers:0:Host=127.0.0.1", "Sparkplug:Port is set beside Sparkplug:Servers" },
        { "Sparkplug:Host=;Sparkplug:Port=;Sparkplug:Servers:0:Host=127.0.0.1;Sparkplug:Servers:1:Host=mqtt://b", "Sparkplug:Servers:1:Host 'mqtt://b' is not a host name or address (no scheme, no port: the port is Sparkplug:Servers:1:Port)" },
        { "Sparkplug:Host=;Sparkplug:Port=;Sparkplug:Servers:0:Host=127.0.0.1;Sparkplug:Servers:0:Port=70000", "Sparkplug:Servers:0:Port must be 1-65535; it is 70000" },
        { "Sparkplug:Host=;Sparkplug:Port=;Sparkplug:Servers:0:Host=127.0.0.1;Sparkplug:Servers:1:Host=127.0.0.1", "Sparkplug:Servers:1 names 127.0.0.1:1883 again (Sparkplug:Servers:0 does already)" },
        { "Sparkplug:Host=;Sparkplug:Port=;Sparkplug:Servers:0:Hots=127.0.0.1", "Sparkplug:Servers:0:Hots is not a setting here" },
        { "Sparkplug:Host=;Sparkplug:Port=;Sparkplug:Servers:0:Host=127.0.0.1;Sparkplug:Servers:0:Tls:CaFile=/x/ca.pem", "Sparkplug:Servers:0:Tls:Enabled is false but CaFile is set" },
        { "Sparkplug:Host=;Sparkplug:Port=;Sparkplug:Servers:first:Host=127.0.0.1", "Sparkplug:Servers:first: Sparkplug:Servers is a list; its items are numbered 0, 1, 2" },
        { "Sparkplug:Host=;Sparkplug:Port=;Sparkplug:Servers:0:Host=127.0.0.1;Sparkplug:Servers:1:Host=127.0.0.2;Sparkplug:Servers:1:Port=8883;Sparkplug:Servers:1:Tls:Enabled=true", "" },
        { "Sparkplug:PrimaryHostLegacyState=true", "Sparkplug:PrimaryHostLegacyState is set without Sparkplug:PrimaryHostId" },
        { "Sparkplug:PrimaryHostId=IamHost;Sparkplug:PrimaryHostLegacyState=true", "" },
        { "Sparkplug:StoreAndForward:Capacity=0", "Sparkplug:StoreAndForward:Capacity must be 1-10000000; it is 0" },
        { "Sparkplug:StoreAndForward:MaxMegabytes=0", "Sparkplug:StoreAndForward:MaxMegabytes must be 1-1048576" },
        { "Sparkplug:StoreAndForward:MaxAge=0s", "Sparkplug:StoreAndForward:MaxAge must be at least 1s" },
        { "Sparkplug:StoreAndForward:Capasity=5", "Sparkplug:StoreAndForward:Capasity is not a setting here" },
        { "Sparkplug:StoreAndForward:Enabled=false;Sparkplug:StoreAndForward:Durable=true", "Sparkplug:StoreAndForward:Durable is true but Sparkplug:StoreAndForward:Enabled is false" },
        { $"Sparkplug:StoreAndForward:Durable=true;Sparkplug:StateDirectory={NotADirectory}/state", "Sparkplug:StoreAndForward:Durable: the store's database" },
    };

    private static string NotADirectory => Path.Combine(AppContext.BaseDirectory, "OmronHostLink.Gateway.Tests.dll");

    [Theory]
    [MemberData(nameof(BadSettings))]
    public void Invalid_sparkplug_configuration_fails_at_start_naming_the_key(string settings, string expected)
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(9, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        config["Sparkplug:Host"] = "127.0.0.1";
        config["Sparkplug:Port"] = "9";
        config["Sparkplug:GroupId"] = "Plant1";
        config["Sparkplug:EdgeNodeId"] = "gw1";
        MqttGatewayConfig.Group(config, "g", "D100");
        MqttGatewayConfig.Group(config, "flag", "T5", "bit");
        foreach (string setting in settings.Split(';'))
        {
            string[] pair = setting.Split('=', 2);
            config[pair[0]] = pair[1];
        }

        using IHost host = MqttGatewayConfig.Build(config, new CapturingLoggerProvider());

        Exception? error = Record.Exception(() => host.Services.GetRequiredService<IOptions<SparkplugOptions>>().Value);
        error ??= Record.Exception(() => host.Services.GetRequiredService<IOptions<GatewayOptions>>().Value);

        if (expected.Length == 0)
        {
            error.Should().BeNull();
            return;
        }

        error.Should().BeOfType<OptionsValidationException>();
        ((OptionsValidationException)error!).Failures.Should().Contain(m => m.Contains(expected, StringComparison.Ordinal), $"the message names the key ({string.Join(" | ", ((OptionsValidationException)error).Failures)})");
    }
}
