using System.Diagnostics.Metrics;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Diagnostics.Metrics.Testing;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Tests.Telemetry;

/// <summary>
/// The meter made through a real <see cref="IMeterFactory"/> (<c>AddMetrics</c>), read with <see cref="MetricCollector{T}"/>:
/// what an application sees through OpenTelemetry or dotnet-counters.
/// </summary>
public sealed class MeterFactoryMetricsTests : IDisposable
{
    private const string Duration = "hostlink.client.operation.duration";
    private readonly ServiceProvider _services = new ServiceCollection().AddMetrics().BuildServiceProvider();

    private IMeterFactory Factory => _services.GetRequiredService<IMeterFactory>();

    [Fact]
    public async Task A_read_records_its_duration_in_seconds_with_the_link_unit_and_command()
    {
        using var durations = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Duration);
        HostLinkClientOptions options = TelemetryLine.Options("press");
        options.MeterFactory = Factory;
        // The PLC waits 100 ms before each answer (its own timer, which may fire a little early): in seconds the
        // duration is about 0.1, in milliseconds it would be about 100.
        await using var line = TelemetryLine.Start(options, new VirtualPlcOptions { Turnaround = TimeSpan.FromMilliseconds(100) });

        await line.Client.ReadWordsAsync("D0", 2);

        CollectedMeasurement<double> m = durations.GetMeasurementSnapshot().Should().ContainSingle().Subject;
        m.Value.Should().BeGreaterThanOrEqualTo(0.08).And.BeLessThan(10);
        m.Tags.Should().Equal(new Dictionary<string, object?>
        {
            ["hostlink.link.name"] = "press",
            ["hostlink.unit"] = 0,
            ["hostlink.command"] = "RD",
        });
        durations.Instrument!.Unit.Should().Be("s");
        ((Histogram<double>)durations.Instrument).Advice!.HistogramBucketBoundaries.Should()
            .StartWith(0.001).And.Contain(0.05).And.BeInAscendingOrder();
    }

    [Fact]
    public async Task Two_clients_with_different_link_names_are_told_apart()
    {
        using var durations = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Duration);
        HostLinkClientOptions pressOptions = TelemetryLine.Options("press");
        pressOptions.MeterFactory = Factory;
        HostLinkClientOptions ovenOptions = TelemetryLine.Options("oven");
        ovenOptions.MeterFactory = Factory;
        await using var press = TelemetryLine.Start(pressOptions);
        await using var oven = TelemetryLine.Start(ovenOptions);

        await press.Client.ReadWordsAsync("D0", 1);
        await oven.Client.ReadWordsAsync("D0", 1);
        await oven.Client.ReadStatusAsync();

        var byLink = durations.GetMeasurementSnapshot()
            .GroupBy(m => (string?)m.Tags["hostlink.link.name"])
            .ToDictionary(g => g.Key!, g => g.Select(m => (string?)m.Tags["hostlink.command"]).ToArray());
        byLink.Should().HaveCount(2);
        byLink["press"].Should().Equal("RD");
        byLink["oven"].Should().Equal("RD", "MS");
    }

    [Fact]
    public async Task Without_a_link_name_the_link_is_named_by_its_transport()
    {
        using var durations = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Duration);
        await using var simulator = new TcpSimulatorHost(new VirtualPlc());
        await simulator.StartAsync();
        HostLinkClientOptions options = TelemetryLine.Options("unused");
        options.LinkName = null;
        options.MeterFactory = Factory;
        await using var client = HostLinkClient.ForTcp("127.0.0.1", simulator.EndPoint.Port, options);

        await client.ReadWordsAsync("D0", 1);

        client.LinkName.Should().Be($"127.0.0.1:{simulator.EndPoint.Port}");
        durations.LastMeasurement!.Tags["hostlink.link.name"].Should().Be(client.LinkName);

        // A serial link is named by its port alone, not its settings (the port opens on first use: nothing is opened here).
        await using var serial = HostLinkClient.ForSerialPort("/dev/ttyUSB7");
        serial.LinkName.Should().Be("/dev/ttyUSB7");
        serial.Description.Should().Be("/dev/ttyUSB7 9600 7E2");
    }

    [Fact]
    public async Task A_timeout_and_an_end_code_record_their_error_type()
    {
        using var durations = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Duration);
        HostLinkClientOptions options = TelemetryLine.Options("line");
        options.MeterFactory = Factory;
        options.TurnaroundAllowance = TimeSpan.FromMilliseconds(100);
        await using var line = TelemetryLine.Start(options, new VirtualPlcOptions { InitialMode = PlcMode.Run });

        await FluentActions.Awaiting(() => line.Client.WriteWordAsync("D0", 1)).Should().ThrowAsync<HostLinkEndCodeException>();
        await FluentActions.Awaiting(() => line.Client.Unit(9).ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();

        IReadOnlyList<CollectedMeasurement<double>> all = durations.GetMeasurementSnapshot();
        all.Should().HaveCount(2);
        all[0].Tags.Should().Contain("error.type", "NotExecutableInRunMode").And.Contain("hostlink.command", "WD").And.Contain("hostlink.unit", 0);
        all[1].Tags.Should().Contain("error.type", "timeout").And.Contain("hostlink.unit", 9).And.Contain("hostlink.command", "RD");
        all[1].Value.Should().BeGreaterThanOrEqualTo(0.09, "a timeout costs the turnaround allowance of 0.1 s (less a timer's slack), not 100");
    }

    [Fact]
    public async Task A_retry_is_counted_with_the_error_of_the_failed_attempt_and_the_read_is_one_operation()
    {
        using var durations = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Duration);
        using var retries = new MetricCollector<long>(Factory, HostLinkTelemetry.MeterName, "hostlink.client.retries");
        HostLinkClientOptions options = TelemetryLine.Options("line");
        options.MeterFactory = Factory;
        options.ReadRetries = 2;
        await using var line = TelemetryLine.Start(options);
        line.Plc.WriteWord(PlcArea.Dm, 0, 0x1234);

        line.CorruptNextAnswer();
        (await line.Client.ReadWordsAsync("D0", 1)).Should().Equal(0x1234);

        CollectedMeasurement<long> retry = retries.GetMeasurementSnapshot().Should().ContainSingle().Subject;
        retry.Value.Should().Be(1);
        retry.Tags.Should().Contain("error.type", "frame_error").And.Contain("hostlink.command", "RD").And.Contain("hostlink.link.name", "line");
        durations.GetMeasurementSnapshot().Should().ContainSingle("the retried read is one operation")
            .Which.Tags.Should().NotContainKey("error.type");
    }

    [Fact]
    public async Task The_open_connection_count_is_observed_per_link_while_the_transport_is_open()
    {
        using var connections = new MetricCollector<long>(Factory, HostLinkTelemetry.MeterName, "hostlink.client.connection.count");
        HostLinkClientOptions options = TelemetryLine.Options("line-a");
        options.MeterFactory = Factory;
        var a = TelemetryLine.Start(options);
        HostLinkClientOptions otherOptions = TelemetryLine.Options("line-b");
        otherOptions.MeterFactory = Factory;
        await using var b = TelemetryLine.Start(otherOptions);

        Dictionary<string, long> Observe()
        {
            connections.Clear();
            connections.RecordObservableInstruments();
            return connections.GetMeasurementSnapshot().ToDictionary(m => (string)m.Tags["hostlink.link.name"]!, m => m.Value);
        }

        Observe().Should().BeEmpty("a stream is opened by the first exchange");
        await a.Client.ReadWordsAsync("D0", 1);
        await a.Client.ReadWordsAsync("D0", 1);
        await b.Client.ReadWordsAsync("D0", 1);
        Observe().Should().Equal(new Dictionary<string, long> { ["line-a"] = 1, ["line-b"] = 1 });

        await a.DisposeAsync();
        Observe().Should().Equal(new Dictionary<string, long> { ["line-b"] = 1 });
    }

    [Fact]
    public async Task A_meter_factory_owns_its_meter_nothing_reaches_another_factory_and_the_client_leaves_it_undisposed()
    {
        using var other = new ServiceCollection().AddMetrics().BuildServiceProvider();
        using var elsewhere = new MetricCollector<double>(other.GetRequiredService<IMeterFactory>(), HostLinkTelemetry.MeterName, Duration);
        using var here = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Duration);
        HostLinkClientOptions options = TelemetryLine.Options("line");
        options.MeterFactory = Factory;
        await using (var line = TelemetryLine.Start(options))
        {
            await line.Client.ReadWordsAsync("D0", 1);
        }

        // A second client on the same factory after the first was disposed still records: the meter lives on.
        await using (var line = TelemetryLine.Start(options))
        {
            await line.Client.ReadWordsAsync("D0", 1);
        }

        here.GetMeasurementSnapshot().Should().HaveCount(2);
        elsewhere.GetMeasurementSnapshot().Should().BeEmpty();
    }

    [Theory]
    [InlineData("")]
    [InlineData("  ")]
    public void An_empty_link_name_is_refused_naming_the_option(string name)
    {
        var options = new HostLinkClientOptions { LinkName = name };

        FluentActions.Invoking(options.Validate).Should().Throw<ArgumentException>()
            .Which.ParamName.Should().Be(nameof(HostLinkClientOptions.LinkName));
    }

    public void Dispose() => _services.Dispose();
}
