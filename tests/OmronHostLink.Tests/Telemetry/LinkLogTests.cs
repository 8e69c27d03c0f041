using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Logging.Testing;
using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Telemetry;

/// <summary>The link's log events, as structured records (<see cref="FakeLogger"/>), not only as text.</summary>
public sealed class LinkLogTests
{
    [Fact]
    public async Task A_damaged_answer_logs_a_retry_warning_and_the_resynchronisation_with_their_fields()
    {
        using var provider = new FakeLoggerProvider();
        using var factory = LoggerFactory.Create(b => b.SetMinimumLevel(LogLevel.Debug).AddProvider(provider));
        HostLinkClientOptions options = TelemetryLine.Options("line");
        options.ReadRetries = 1;
        options.LoggerFactory = factory;
        await using var line = TelemetryLine.Start(options);

        line.CorruptNextAnswer();
        await line.Client.ReadWordsAsync("D0", 1);

        List<FakeLogRecord> records = provider.Collector.GetSnapshot().ToList();
        FakeLogRecord retry = records.Should().ContainSingle(r => r.Level == LogLevel.Warning && r.Id.Id != 8, "the in-memory line's fence comes back faster than the 9600 bps it is configured for, which is its own warning").Subject;
        retry.Category.Should().Be("OmronHostLink");
        retry.Id.Id.Should().Be(3);
        retry.GetStructuredStateValue("Unit").Should().Be("0");
        retry.GetStructuredStateValue("Header").Should().Be("RD");
        retry.GetStructuredStateValue("Attempt").Should().Be("1");
        retry.GetStructuredStateValue("Retries").Should().Be("1");
        retry.Message.Should().Contain("retry 1 of 1");

        FakeLogRecord resync = records.Should().ContainSingle(r => r.Id.Id == 4).Subject;
        resync.Level.Should().Be(LogLevel.Debug);
        resync.GetStructuredStateValue("Outcome").Should().Be("Answered");

        records.Where(r => r.Id.Id == 2).Should().ContainSingle("only the retried attempt completed")
            .Which.GetStructuredStateValue("Header").Should().Be("RD");
        records.IndexOf(retry).Should().BeLessThan(records.IndexOf(resync), "the link resynchronises before it repeats the command");
    }
}
