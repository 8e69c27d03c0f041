using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Simulator;
using OmronHostLink.Gateway.Mqtt;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>Brokers that require a password (with per-user ACLs) or TLS.</summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttSecurityTests(ITestOutputHelper output) : IAsyncLifetime
{
    /// <summary>The ACL of docs/deployment.md, with the prefix "test" for "plant1" and the link "plc" for "line1".</summary>
    private const string Acl = """
        # /etc/mosquitto/acl — one block per worker and per consumer
        user worker-a
        topic readwrite test/status/worker-a
        topic write test/plc/#
        topic read test/plc/+/+/set

        user scada
        topic read test/#
        topic write test/+/+/+/set
        # replies to its own response topics
        topic readwrite scada/replies/#

        user historian
        topic read test/#
        """;

    private readonly List<IAsyncDisposable> _cleanup = new();
    private readonly CapturingLoggerProvider _logs = new();
    private RecordingSimulator _simulator = null!;
    private VirtualPlc _plc = null!;

    public async Task InitializeAsync()
    {
        _plc = new VirtualPlc();
        _plc.WriteWords("D100", [77]);
        _simulator = await RecordingSimulator.StartAsync(_plc);
    }

    public async Task DisposeAsync()
    {
        foreach (IAsyncDisposable d in Enumerable.Reverse(_cleanup))
        {
            await d.DisposeAsync();
        }

        await _simulator.DisposeAsync();
        output.WriteLine(_logs.Dump());
    }

    [Fact]
    public async Task With_username_and_password_the_worker_publishes_and_takes_writes_within_its_acl()
    {
        MosquittoBroker broker = await Broker(PasswordSettings());
        TestSubscriber scada = await Subscriber(broker, "scada", "scada-secret");
        await StartWorker(broker, config =>
        {
            config["Mqtt:ClientId"] = "worker-a";
            config["Mqtt:Username"] = "worker-a";
            config["Mqtt:Password"] = "worker-a-secret";
            config["Mqtt:Writes:Enabled"] = "true";
            MqttGatewayConfig.Group(config, "setpoint", "D500", intervalMs: 50, writable: true);
        });

        ReceivedMessage level = await scada.WaitForAsync(MqttGatewayConfig.Topic("level"));
        level.Payload.Should().Contain("\"value\":77");
        await scada.WaitForAsync($"{MqttGatewayConfig.Prefix}/status/worker-a", m => m.Payload == "online");
        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.WritesAccepted).Count > 0, "the worker subscribes to its command topics", _logs);

        await scada.PublishAsync(MqttGatewayConfig.Topic("setpoint") + "/set", "321");

        ReceivedMessage reply = await scada.WaitForAsync(MqttGatewayConfig.Topic("setpoint") + "/set/result");
        reply.Payload.Should().Contain("\"status\":\"done\"");
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)321]);
        _logs.WithEvent(MqttLog.Events.PublishRefused).Should().BeEmpty();
        _logs.WithEvent(MqttLog.Events.SubscribeRefused).Should().BeEmpty();
    }

    [Fact]
    public async Task A_wrong_password_is_reported_and_retried_without_publishing()
    {
        MosquittoBroker broker = await Broker(PasswordSettings());
        TestSubscriber scada = await Subscriber(broker, "scada", "scada-secret");
        await StartWorker(broker, config =>
        {
            config["Mqtt:ClientId"] = "worker-a";
            config["Mqtt:Username"] = "worker-a";
            config["Mqtt:Password"] = "wrong";
        });

        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.StillUnreachable).Count >= 2, "several refused attempts", _logs);
        LogEntry warning = _logs.WithEvent(MqttLog.Events.Unreachable).Should().ContainSingle().Subject;
        warning.Level.Should().Be(LogLevel.Warning);
        ((string?)warning["Reason"]).Should().MatchRegex("(?i)(BadUserNameOrPassword|NotAuthorized)");
        scada.Messages.Should().BeEmpty();
    }

    [Fact]
    public async Task Over_tls_the_worker_trusts_the_private_ca_from_its_ca_file()
    {
        using var certificates = TestCertificates.Create();
        MosquittoBroker broker = await Broker(new MosquittoSettings { Tls = certificates });
        string caFile = certificates.WriteAuthority(Path.Combine(broker.Directory, "worker-ca.pem"));
        TestSubscriber subscriber = await Subscriber(broker);
        await StartWorker(broker, config =>
        {
            config["Mqtt:Tls:Enabled"] = "true";
            config["Mqtt:Tls:CaFile"] = caFile;
        });

        ReceivedMessage level = await subscriber.WaitForAsync(MqttGatewayConfig.Topic("level"));
        level.Payload.Should().Contain("\"value\":77");
        _logs.WithEvent(MqttLog.Events.UntrustedCertificates).Should().BeEmpty();
    }

    [Fact]
    public async Task Over_tls_a_broker_certificate_from_another_ca_is_refused()
    {
        using var certificates = TestCertificates.Create();
        using var other = TestCertificates.Create("Someone else's CA");
        MosquittoBroker broker = await Broker(new MosquittoSettings { Tls = certificates });
        string wrongCa = other.WriteAuthority(Path.Combine(broker.Directory, "other-ca.pem"));
        TestSubscriber subscriber = await Subscriber(broker);
        await StartWorker(broker, config =>
        {
            config["Mqtt:Tls:Enabled"] = "true";
            config["Mqtt:Tls:CaFile"] = wrongCa;
        });

        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.StillUnreachable).Count >= 2, "several refused attempts", _logs);
        ((string?)_logs.WithEvent(MqttLog.Events.Unreachable).Should().ContainSingle().Subject["Reason"])
            .Should().Contain("does not chain to a CA in Mqtt:Tls:CaFile");
        subscriber.Messages.Should().BeEmpty("nothing is sent to a broker that is not trusted");
    }

    [Fact]
    public async Task Over_tls_without_a_ca_file_the_system_roots_do_not_trust_a_private_ca()
    {
        using var certificates = TestCertificates.Create();
        MosquittoBroker broker = await Broker(new MosquittoSettings { Tls = certificates });
        TestSubscriber subscriber = await Subscriber(broker);
        await StartWorker(broker, config => config["Mqtt:Tls:Enabled"] = "true");

        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.StillUnreachable).Count >= 2, "several refused attempts", _logs);
        ((string?)_logs.WithEvent(MqttLog.Events.Unreachable).Should().ContainSingle().Subject["Reason"])
            .Should().Contain("not trusted by this machine's root certificates");
        subscriber.Messages.Should().BeEmpty();
    }

    [Fact]
    public async Task Allowing_untrusted_certificates_connects_and_warns()
    {
        using var certificates = TestCertificates.Create();
        MosquittoBroker broker = await Broker(new MosquittoSettings { Tls = certificates });
        TestSubscriber subscriber = await Subscriber(broker);
        await StartWorker(broker, config =>
        {
            config["Mqtt:Tls:Enabled"] = "true";
            config["Mqtt:Tls:AllowUntrustedCertificates"] = "true";
        });

        await subscriber.WaitForAsync(MqttGatewayConfig.Topic("level"));
        _logs.WithEvent(MqttLog.Events.UntrustedCertificates).Should().ContainSingle().Which.Level.Should().Be(LogLevel.Warning);
    }

    private static MosquittoSettings PasswordSettings()
    {
        var settings = new MosquittoSettings { Acl = Acl };
        settings.Users["worker-a"] = "worker-a-secret";
        settings.Users["scada"] = "scada-secret";
        return settings;
    }

    private async Task<MosquittoBroker> Broker(MosquittoSettings settings)
    {
        MosquittoBroker broker = await MosquittoBroker.StartAsync(settings);
        _cleanup.Add(new BrokerLog(broker, output));
        return broker;
    }

    private async Task<TestSubscriber> Subscriber(MosquittoBroker broker, string? username = null, string? password = null)
    {
        TestSubscriber subscriber = await TestSubscriber.ConnectAsync(broker, [$"{MqttGatewayConfig.Prefix}/#"], username: username, password: password);
        _cleanup.Add(subscriber);
        return subscriber;
    }

    private async Task StartWorker(MosquittoBroker broker, Action<Dictionary<string, string?>> configure)
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(_simulator.Port, broker);
        MqttGatewayConfig.Group(config, "level", "D100", intervalMs: 50);
        configure(config);
        IHost host = MqttGatewayConfig.Build(config, _logs);
        _cleanup.Add(new AsyncHost(host));
        await host.StartAsync();
    }


    private sealed class BrokerLog(MosquittoBroker broker, ITestOutputHelper output) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            output.WriteLine("mosquitto:" + Environment.NewLine + broker.Log);
            await broker.DisposeAsync();
        }
    }
}
