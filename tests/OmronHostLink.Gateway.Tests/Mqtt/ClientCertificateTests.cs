using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Tests.Sparkplug;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// Mosquitto with <c>require_certificate true</c>: the gateway's client certificate (PEM with its key, or PKCS#12),
/// made by the test with <c>CertificateRequest</c> and signed by the broker's CA, lets both outputs in; one that has
/// expired stops the start with one message naming its key; one from another CA is refused by the broker, said once,
/// naming its key.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class ClientCertificateTests(ITestOutputHelper output) : IAsyncLifetime
{
    private readonly TestCertificates _authority = TestCertificates.Create();
    private readonly string _directory = Directory.CreateTempSubdirectory("ohl-client-certificates-").FullName;
    private readonly CapturingLoggerProvider _logs = new();
    private readonly List<IAsyncDisposable> _cleanup = [];
    private MosquittoBroker _broker = null!;
    private RecordingSimulator _simulator = null!;
    private string _caFile = null!;

    public async Task InitializeAsync()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [77]);
        _simulator = await RecordingSimulator.StartAsync(plc);
        _broker = await MosquittoBroker.StartAsync(new MosquittoSettings { Tls = _authority, RequireCertificate = true });
        _caFile = _authority.WriteAuthority(Path.Combine(_directory, "ca.pem"));
    }

    public async Task DisposeAsync()
    {
        foreach (IAsyncDisposable item in Enumerable.Reverse(_cleanup))
        {
            await item.DisposeAsync();
        }

        output.WriteLine(_logs.Dump());
        output.WriteLine("mosquitto:" + Environment.NewLine + _broker.Log);
        await _broker.DisposeAsync();
        await _simulator.DisposeAsync();
        _authority.Dispose();
        Directory.Delete(_directory, recursive: true);
    }

    [Fact]
    public async Task A_pem_certificate_and_key_signed_by_the_brokers_ca_let_the_json_output_in()
    {
        (string certificate, string? key) = _authority.WriteClient(_directory, "gateway-pem");
        TestSubscriber subscriber = await Subscriber();
        await StartAsync(config =>
        {
            Tls(config, "Mqtt");
            config["Mqtt:Tls:ClientCertificateFile"] = certificate;
            config["Mqtt:Tls:ClientKeyFile"] = key;
        });

        (await subscriber.WaitForAsync(MqttGatewayConfig.Topic("level"))).Payload.Should().Contain("\"value\":77");
        _logs.WithEvent(MqttLog.Events.Unreachable).Should().BeEmpty();
    }

    [Fact]
    public async Task A_pkcs12_file_with_its_password_lets_the_sparkplug_node_in()
    {
        (string pfx, _) = _authority.WriteClient(_directory, "gateway-pfx", pkcs12Password: "s3cret");
        TestSubscriber subscriber = await Subscriber();
        await StartAsync(
            config =>
            {
                Tls(config, "Sparkplug");
                config["Sparkplug:Tls:ClientCertificateFile"] = pfx;
                config["Sparkplug:Tls:ClientKeyPassword"] = "s3cret";
            },
            sparkplug: true);

        await subscriber.WaitUntilAsync(ms => SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.NBirth) && SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.Device("DBIRTH", "plc-0")), "the node is born");
        _logs.WithEvent(1302).Should().BeEmpty();
    }

    [Fact]
    public async Task An_expired_certificate_stops_the_start_with_one_message_naming_its_key()
    {
        DateTimeOffset now = DateTimeOffset.UtcNow;
        (string certificate, string? key) = _authority.WriteClient(_directory, "gateway-expired", notBefore: now.AddHours(-20), notAfter: now.AddMinutes(-5));
        string root = Directory.CreateTempSubdirectory("ohl-gateway-").FullName;
        try
        {
            await File.WriteAllTextAsync(Path.Combine(root, "appsettings.json"), """
                {
                  "Logging": { "LogLevel": { "Default": "Warning" } },
                  "HostLink": { "Links": { "plc": { "Tcp": "127.0.0.1:9", "Groups": { "level": { "Address": "D100" } } } } }
                }
                """);
            var error = new StringWriter();
            int exit = await GatewayProgram.RunAsync(
            [
                "--contentRoot", root,
                "--Mqtt:Host=127.0.0.1", $"--Mqtt:Port={_broker.Port}",
                "--Mqtt:Tls:Enabled=true", $"--Mqtt:Tls:CaFile={_caFile}",
                $"--Mqtt:Tls:ClientCertificateFile={certificate}", $"--Mqtt:Tls:ClientKeyFile={key}",
            ], error).WaitAsync(TimeSpan.FromSeconds(60));

            string message = error.ToString();
            output.WriteLine(message);
            exit.Should().Be(2, message);
            message.Split("the configuration is not valid").Should().HaveCount(2, "one message");
            message.Should().Contain($"Mqtt:Tls:ClientCertificateFile '{certificate}': the certificate CN=gateway-expired expired on");
            message.Should().NotMatchRegex(@"(?m)^\s+at ", "no stack trace");
        }
        finally
        {
            Directory.Delete(root, recursive: true);
        }
    }

    [Fact]
    public async Task A_certificate_from_another_ca_is_refused_by_the_broker_and_said_once_naming_its_key()
    {
        using TestCertificates stranger = TestCertificates.Create("Someone else's CA");
        (string certificate, string? key) = stranger.WriteClient(_directory, "gateway-stranger");
        TestSubscriber subscriber = await Subscriber();
        await StartAsync(config =>
        {
            Tls(config, "Mqtt");
            config["Mqtt:Tls:ClientCertificateFile"] = certificate;
            config["Mqtt:Tls:ClientKeyFile"] = key;
        });

        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.StillUnreachable).Count >= 2, "several refused attempts", _logs);
        LogEntry refused = _logs.WithEvent(MqttLog.Events.Unreachable).Should().ContainSingle("said once per outage").Subject;
        refused.Level.Should().Be(LogLevel.Warning);
        ((string?)refused["Reason"]).Should().StartWith("the broker refused the client certificate of Mqtt:Tls:ClientCertificateFile (CN=gateway-stranger, issued by CN=Someone else's CA)");
        subscriber.Messages.Should().BeEmpty();
    }

    [Theory]
    [InlineData("no key", "Mqtt:Tls:ClientCertificateFile '{cert}' is a PEM certificate: set Mqtt:Tls:ClientKeyFile to its private key")]
    [InlineData("another certificate's key", "Mqtt:Tls:ClientKeyFile '{otherkey}' is not the key of Mqtt:Tls:ClientCertificateFile '{cert}' (CN=gateway-a)")]
    [InlineData("a missing certificate", "Mqtt:Tls:ClientCertificateFile '{missing}' does not exist")]
    [InlineData("a wrong PKCS#12 password", "Mqtt:Tls:ClientCertificateFile '{pfx}' cannot be opened with Mqtt:Tls:ClientKeyPassword")]
    [InlineData("a key without a certificate", "Mqtt:Tls:ClientKeyFile is set without Mqtt:Tls:ClientCertificateFile")]
    [InlineData("a certificate without TLS", "Mqtt:Tls:Enabled is false but ClientCertificateFile is set")]
    [InlineData("a server's own certificate that has expired", "Mqtt:Servers:1:Tls:ClientCertificateFile '{expired}': the certificate CN=gateway-old expired on")]
    public void A_certificate_that_cannot_be_used_is_named_by_its_key(string mistake, string expected)
    {
        (string cert, string? key) = _authority.WriteClient(_directory, "gateway-a");
        (_, string? otherKey) = _authority.WriteClient(_directory, "gateway-b");
        (string pfx, _) = _authority.WriteClient(_directory, "gateway-c", pkcs12Password: "right");
        DateTimeOffset now = DateTimeOffset.UtcNow;
        (string expired, string? expiredKey) = _authority.WriteClient(_directory, "gateway-old", notBefore: now.AddHours(-20), notAfter: now.AddHours(-1));
        string missing = Path.Combine(_directory, "missing.pem");
        var options = new MqttOptions { Host = "127.0.0.1", Tls = new MqttTlsOptions { Enabled = true, CaFile = _caFile } };
        switch (mistake)
        {
            case "no key":
                options.Tls.ClientCertificateFile = cert;
                break;
            case "another certificate's key":
                (options.Tls.ClientCertificateFile, options.Tls.ClientKeyFile) = (cert, otherKey);
                break;
            case "a missing certificate":
                (options.Tls.ClientCertificateFile, options.Tls.ClientKeyFile) = (missing, key);
                break;
            case "a wrong PKCS#12 password":
                (options.Tls.ClientCertificateFile, options.Tls.ClientKeyPassword) = (pfx, "wrong");
                break;
            case "a key without a certificate":
                options.Tls.ClientKeyFile = key;
                break;
            case "a certificate without TLS":
                options.Tls = new MqttTlsOptions { ClientCertificateFile = cert };
                break;
            default:
                options.Host = "";
                options.Servers.Add(new MqttServerOptions { Host = "127.0.0.1", Port = 8883 });
                options.Servers.Add(new MqttServerOptions { Host = "127.0.0.2", Port = 8883, Tls = new MqttTlsOptions { Enabled = true, CaFile = _caFile, ClientCertificateFile = expired, ClientKeyFile = expiredKey } });
                break;
        }

        var failures = new List<string>();
        MqttBrokerOptionsValidator.Validate(options, MqttOptions.SectionName, failures);

        string text = expected.Replace("{cert}", cert, StringComparison.Ordinal).Replace("{otherkey}", otherKey, StringComparison.Ordinal)
            .Replace("{missing}", missing, StringComparison.Ordinal).Replace("{pfx}", pfx, StringComparison.Ordinal).Replace("{expired}", expired, StringComparison.Ordinal);
        failures.Should().ContainSingle(mistake).Which.Should().StartWith(text);
    }

    private static void Tls(Dictionary<string, string?> config, string section)
    {
        config[$"{section}:Tls:Enabled"] = "true";
    }

    private async Task<TestSubscriber> Subscriber()
    {
        TestSubscriber subscriber = await TestSubscriber.ConnectAsync(_broker, [MqttGatewayConfig.Prefix + "/#", SparkplugEndToEndTests.Namespace + "/#"]);
        _cleanup.Add(subscriber);
        return subscriber;
    }

    private async Task StartAsync(Action<Dictionary<string, string?>> configure, bool sparkplug = false)
    {
        Dictionary<string, string?> config = sparkplug ? SparkplugEndToEndTests.Config(_simulator.Port, _broker) : MqttGatewayConfig.Create(_simulator.Port, _broker);
        MqttGatewayConfig.Group(config, "level", "D100", intervalMs: 50);
        string section = sparkplug ? "Sparkplug" : "Mqtt";
        config[$"{section}:Tls:CaFile"] = _caFile;
        configure(config);
        IHost host = MqttGatewayConfig.Build(config, _logs);
        _cleanup.Add(new StoppedHost(host));
        await host.StartAsync();
    }

    private sealed class StoppedHost(IHost host) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            await host.StopAsync();
            host.Dispose();
        }
    }
}
