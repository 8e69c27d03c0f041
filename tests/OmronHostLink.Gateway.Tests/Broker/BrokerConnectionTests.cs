using Microsoft.Extensions.Logging.Abstractions;
using Microsoft.Extensions.Time.Testing;
using MQTTnet;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Mqtt;

namespace OmronHostLink.Gateway.Tests.Broker;

/// <summary>The walk through a server list and the backoff between rounds, and the connection's snapshot.</summary>
public sealed class BrokerConnectionTests
{
    private static readonly TimeSpan Initial = TimeSpan.FromSeconds(1);
    private static readonly TimeSpan Max = TimeSpan.FromSeconds(8);

    [Fact]
    public async Task With_one_server_each_failure_waits_Initial_doubling_up_to_Max()
    {
        await using MqttBrokerConnection connection = Connection(new MqttOptions { Host = "127.0.0.1", Port = 1, Reconnect = new BackoffOptions { Initial = Initial, Max = Max } });

        var delays = new List<double>();
        for (int i = 0; i < 6; i++)
        {
            ConnectionEnd end = await connection.FailedAsync(new InvalidOperationException("refused"));
            end.Next.Should().Be(connection.Servers[0]);
            delays.Add(end.Delay.TotalSeconds);
        }

        delays.Should().Equal(1, 2, 4, 8, 8, 8);
    }

    [Fact]
    public async Task A_list_is_walked_at_once_and_the_backoff_doubles_after_each_round_of_failures()
    {
        var options = new MqttOptions { Reconnect = new BackoffOptions { Initial = Initial, Max = Max } };
        options.Servers.Add(new MqttServerOptions { Host = "127.0.0.1", Port = 1 });
        options.Servers.Add(new MqttServerOptions { Host = "127.0.0.1", Port = 2 });
        options.Servers.Add(new MqttServerOptions { Host = "127.0.0.1", Port = 3, Tls = new MqttTlsOptions { Enabled = true, AllowUntrustedCertificates = true } });
        await using MqttBrokerConnection connection = Connection(options);
        connection.Servers.Select(s => (s.Address, s.Key, s.Tls.Enabled)).Should().Equal(("127.0.0.1:1", "Mqtt:Servers:0", false), ("127.0.0.1:2", "Mqtt:Servers:1", false), ("127.0.0.1:3", "Mqtt:Servers:2", true));

        var steps = new List<(int Failed, int Next, double Delay, bool First)>();
        for (int i = 0; i < 7; i++)
        {
            ConnectionEnd end = await connection.FailedAsync(new InvalidOperationException("refused"));
            steps.Add((end.Server.Index, end.Next.Index, end.Delay.TotalSeconds, end.FirstFailure));
        }

        steps.Should().Equal((0, 1, 0, true), (1, 2, 0, false), (2, 0, 1, false), (0, 1, 0, false), (1, 2, 0, false), (2, 0, 2, false), (0, 1, 0, false));
        BrokerStatus status = connection.Status();
        status.State.Should().Be(BrokerState.Waiting);
        (status.Server, status.ServerKey, status.ServerNumber, status.FailedAttempts).Should().Be(("127.0.0.1:2", "Mqtt:Servers:1", 2, 7));
        status.Servers.Should().Equal("127.0.0.1:1", "127.0.0.1:2", "127.0.0.1:3");
        status.LastProblem.Should().Be("refused");
        status.Output.Should().Be("mqtt");
    }

    private static MqttBrokerConnection Connection(MqttOptions options)
        => new(options, MqttOptions.SectionName, "MQTT", new MqttClientFactory(), new FakeTimeProvider(), NullLogger.Instance);
}
