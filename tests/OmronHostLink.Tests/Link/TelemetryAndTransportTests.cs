using System.Collections.Concurrent;
using System.Diagnostics.Metrics;
using System.Net;
using System.Net.Sockets;
using Microsoft.Extensions.Logging;
using OmronHostLink.Link;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Link;

public sealed class TelemetryAndTransportTests
{
    private static HostLinkClientOptions Fast(ILoggerFactory? logging = null) => new()
    {
        LineTiming = new LineTiming(115200, 11),
        // These tests are about what is counted and logged, not about timing.
        TurnaroundAllowance = Allowances.LosslessLine,
        ReadRetries = 0,
        LoggerFactory = logging,
    };

    [Fact]
    public async Task A_serial_port_that_cannot_open_names_the_port_and_the_reason()
    {
        await using var client = HostLinkClient.ForSerialPort("/tmp/no-such-port-for-hostlink", Fast());

        var e = await FluentActions.Awaiting(() => client.ReadStatusAsync()).Should().ThrowAsync<HostLinkConnectionException>();

        e.Which.Message.Should().Contain("/tmp/no-such-port-for-hostlink").And.Contain("does not exist");
    }

    [Fact]
    public async Task A_gateway_that_refuses_the_connection_is_a_connection_error_naming_it()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        listener.Stop();
        await using var client = HostLinkClient.ForTcp("127.0.0.1", port, Fast(), TimeSpan.FromSeconds(2));

        var e = await FluentActions.Awaiting(() => client.ReadStatusAsync()).Should().ThrowAsync<HostLinkConnectionException>();

        e.Which.Message.Should().Contain($"127.0.0.1:{port}");
    }

    [Fact]
    public async Task Without_a_meter_factory_the_shared_static_meter_records_durations_and_error_types()
    {
        var measurements = new ConcurrentBag<(string Instrument, double Value, Dictionary<string, object?> Tags)>();
        using var listener = new MeterListener();
        listener.InstrumentPublished = (instrument, l) =>
        {
            // The static meter has no factory scope; meters from factories in other tests are left out.
            if (instrument.Meter.Name == HostLinkTelemetry.MeterName && instrument.Meter.Scope is null)
            {
                l.EnableMeasurementEvents(instrument);
            }
        };
        listener.SetMeasurementEventCallback<long>((i, v, tags, _) => measurements.Add((i.Name, v, ToDictionary(tags))));
        listener.SetMeasurementEventCallback<double>((i, v, tags, _) => measurements.Add((i.Name, v, ToDictionary(tags))));
        listener.Start();

        var plc = new VirtualPlc(new VirtualPlcOptions { InitialMode = PlcMode.Run });
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = plc.RunAsync(plcEnd, stop.Token);
        HostLinkClientOptions options = Fast();
        options.LinkName = "static-meter-test";
        await using (var client = HostLinkClient.ForStream(host, options))
        {
            await client.ReadWordsAsync("D0", 2);
            await FluentActions.Awaiting(() => client.WriteWordAsync("D0", 1)).Should().ThrowAsync<HostLinkEndCodeException>();
            await FluentActions.Awaiting(() => client.Unit(9).ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();
        }

        stop.Cancel();
        listener.RecordObservableInstruments();
        // Tests in other classes use the same static meter: only this test's link is looked at.
        var mine = measurements.Where(m => (string?)m.Tags["hostlink.link.name"] == "static-meter-test").ToList();
        mine.Should().Contain(m => m.Instrument == "hostlink.client.operation.duration" && (string?)m.Tags["hostlink.command"] == "RD" && m.Tags["error.type"] == null && m.Value > 0);
        mine.Should().Contain(m => m.Instrument == "hostlink.client.operation.duration" && (string?)m.Tags["hostlink.command"] == "WD" && (string?)m.Tags["error.type"] == "NotExecutableInRunMode");
        mine.Should().Contain(m => m.Instrument == "hostlink.client.operation.duration" && (int?)m.Tags["hostlink.unit"] == 9 && (string?)m.Tags["error.type"] == "timeout");
    }

    [Fact]
    public async Task Frames_are_logged_at_trace_and_transactions_at_debug()
    {
        using var provider = new CapturingLoggerProvider();
        using var factory = LoggerFactory.Create(b => b.SetMinimumLevel(LogLevel.Trace).AddProvider(provider));
        var plc = new VirtualPlc();
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        _ = plc.RunAsync(plcEnd, stop.Token);
        await using (var client = HostLinkClient.ForStream(host, Fast(factory)))
        {
            await client.ReadModelAsync();
        }

        stop.Cancel();
        provider.Entries.Should().Contain(e => e.Level == LogLevel.Trace && e.Message.Contains(">> @00MM", StringComparison.Ordinal));
        provider.Entries.Should().Contain(e => e.Level == LogLevel.Trace && e.Message.Contains("<< @00MM00", StringComparison.Ordinal));
        provider.Entries.Should().Contain(e => e.Level == LogLevel.Debug && e.Message.Contains("MM completed", StringComparison.Ordinal));
    }

    private static Dictionary<string, object?> ToDictionary(ReadOnlySpan<KeyValuePair<string, object?>> tags)
    {
        var d = new Dictionary<string, object?>();
        foreach (var t in tags)
        {
            d[t.Key] = t.Value;
        }

        d.TryAdd("hostlink.link.name", null);
        d.TryAdd("hostlink.command", null);
        d.TryAdd("hostlink.unit", null);
        d.TryAdd("error.type", null);
        return d;
    }
}
