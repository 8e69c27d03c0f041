using System.Diagnostics.Metrics;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Diagnostics.Metrics.Testing;
using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Telemetry;

/// <summary>
/// <c>hostlink.client.exchange.duration</c>: the answered attempt of a command that succeeded, first frame out to the
/// answer's last frame — the unit's response time, without the wait for the line or failed attempts.
/// </summary>
public sealed class ExchangeDurationTests : IDisposable
{
    private const string Exchange = "hostlink.client.exchange.duration";
    private const string Operation = "hostlink.client.operation.duration";
    private readonly ServiceProvider _services = new ServiceCollection().AddMetrics().BuildServiceProvider();

    private IMeterFactory Factory => _services.GetRequiredService<IMeterFactory>();

    public void Dispose() => _services.Dispose();

    [Fact]
    public async Task A_read_records_its_response_time_without_the_wait_for_the_line()
    {
        using var exchanges = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Exchange);
        using var operations = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Operation);
        HostLinkClientOptions options = TelemetryLine.Options("press");
        options.MeterFactory = Factory;
        await using var line = TelemetryLine.Start(options, new VirtualPlcOptions { Turnaround = TimeSpan.FromMilliseconds(100) });

        // Two reads at once: the second waits for the first's exchange at the link's gate.
        await Task.WhenAll(line.Client.ReadWordsAsync("D0", 1), line.Client.ReadWordsAsync("D10", 1));

        IReadOnlyList<CollectedMeasurement<double>> answered = exchanges.GetMeasurementSnapshot();
        answered.Should().HaveCount(2);
        answered.Should().OnlyContain(m => m.Value >= 0.08, "each answer took the PLC's 100 ms turnaround (less a timer's slack)");
        answered[0].Tags.Should().Equal(new Dictionary<string, object?>
        {
            ["hostlink.link.name"] = "press",
            ["hostlink.unit"] = 0,
            ["hostlink.command"] = "RD",
        });
        double waited = operations.GetMeasurementSnapshot().Sum(m => m.Value) - answered.Sum(m => m.Value);
        waited.Should().BeGreaterThanOrEqualTo(0.08, "the second read waited for the first's exchange, which its operation counts and its exchange does not");
        exchanges.Instrument!.Unit.Should().Be("s");
    }

    [Fact]
    public async Task Failures_and_probes_record_no_response_time_and_a_retried_read_only_its_answered_attempt()
    {
        using var exchanges = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Exchange);
        using var operations = new MetricCollector<double>(Factory, HostLinkTelemetry.MeterName, Operation);
        HostLinkClientOptions options = TelemetryLine.Options("line");
        options.MeterFactory = Factory;
        options.TurnaroundAllowance = TimeSpan.FromMilliseconds(300);
        options.ReadRetries = 1;
        await using var line = TelemetryLine.Start(options, new VirtualPlcOptions { InitialMode = PlcMode.Run });

        await FluentActions.Awaiting(() => line.Client.Unit(9).ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();
        await FluentActions.Awaiting(() => line.Client.WriteWordAsync("D0", 1)).Should().ThrowAsync<HostLinkEndCodeException>();
        (await line.Client.Unit(9).ProbeAsync()).Should().BeNull();
        (await line.Client.ProbeAsync()).Should().NotBeNull();
        exchanges.GetMeasurementSnapshot().Should().BeEmpty("no command succeeded, and a probe is not a command");

        line.CorruptNextAnswer();
        await line.Client.ReadWordsAsync("D0", 1);

        double exchange = exchanges.GetMeasurementSnapshot().Should().ContainSingle().Subject.Value;
        double operation = operations.GetMeasurementSnapshot().Last().Value;
        exchange.Should().BeLessThan(operation, "the damaged first attempt and the fence after it are the operation's, not the response time");
    }
}
