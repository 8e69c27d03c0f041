using System.Text;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;
using OmronHostLink.Simulator.Hosting;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Telemetry;

/// <summary>
/// The library's instruments read from outside the process, through the runtime's <c>System.Diagnostics.Metrics</c>
/// EventPipe provider: the mechanism <c>dotnet-counters monitor --counters OmronHostLink</c> uses.
/// </summary>
public sealed class EventPipeMetricsTests(ITestOutputHelper output)
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(60);

    [Fact]
    [Trait("Category", "Slow")]
    public async Task A_running_worker_publishes_the_OmronHostLink_instruments_to_an_EventPipe_session_per_link()
    {
        // The press is on a 9600 bps line (the simulator paces its answers), the oven on 115200.
        var pressPlc = new VirtualPlc(new VirtualPlcOptions { BaudRate = 9600 });
        pressPlc.WriteWords(PlcArea.Dm, 100, new ushort[] { 120, 65196, 560, 780 });
        await using var press = new TcpSimulatorHost(pressPlc);
        await press.StartAsync();
        // The oven's line is noisy: now and then an answer arrives damaged and is read again.
        var ovenPlc = new VirtualPlc(new VirtualPlcOptions { BaudRate = 115200, Faults = new FaultOptions { Seed = 5, Corrupt = 0.05 } });
        await using var oven = new TcpSimulatorHost(ovenPlc);
        await oven.StartAsync();

        await using GatewayProcess worker = GatewayProcess.Start(
        [
            $"--HostLink:Links:press:Tcp=127.0.0.1:{press.EndPoint.Port}",
            "--HostLink:Links:press:Serial:BaudRate=9600",
            "--HostLink:Links:press:Groups:counter:Address=D0",
            "--HostLink:Links:press:Groups:counter:Interval=00:00:00.200",
            "--HostLink:Links:press:Groups:levels:Address=D100",
            "--HostLink:Links:press:Groups:levels:Count=4",
            "--HostLink:Links:press:Groups:levels:Type=int16",
            "--HostLink:Links:press:Groups:levels:Interval=00:00:00.500",
            // No PLC answers as unit 5 on the press line: its reads time out.
            "--HostLink:Links:press:Groups:spare:Unit=5",
            "--HostLink:Links:press:Groups:spare:Address=D0",
            "--HostLink:Links:press:Groups:spare:Interval=00:00:01",
            $"--HostLink:Links:oven:Tcp=127.0.0.1:{oven.EndPoint.Port}",
            "--HostLink:Links:oven:Serial:BaudRate=115200",
            "--HostLink:Links:oven:Groups:temperature:Address=D200",
            "--HostLink:Links:oven:Groups:temperature:Type=float",
            "--HostLink:Links:oven:Groups:temperature:Interval=00:00:00.100",
            "--Logging:LogLevel:Default=Warning",
            "--Logging:LogLevel:OmronHostLink.Gateway=Information",
        ]);
        (await worker.WaitForOutputAsync("link oven: polling", Patience) && await worker.WaitForOutputAsync("link press: polling", Patience))
            .Should().BeTrue("the worker starts both links: {0}", worker.Output);

        await using var session = MetricsEventPipeSession.Start(worker.Id, HostLinkTelemetry.MeterName, TimeSpan.FromSeconds(1));
        bool published = await session.WaitForAsync(
            values => Has(values, "HistogramValuePublished", "hostlink.client.operation.duration", "hostlink.command=RD,hostlink.link.name=press,hostlink.unit=0")
                && Has(values, "HistogramValuePublished", "hostlink.client.operation.duration", "hostlink.link.name=oven")
                && Has(values, "HistogramValuePublished", "hostlink.client.operation.duration", "error.type=timeout,")
                && Has(values, "UpDownCounterRateValuePublished", "hostlink.client.connection.count", "hostlink.link.name=oven")
                && Has(values, "UpDownCounterRateValuePublished", "hostlink.client.connection.count", "hostlink.link.name=press"),
            Patience);
        IReadOnlyList<PublishedValue> values = session.Values;
        output.WriteLine(Describe(values));

        published.Should().BeTrue("the worker's OmronHostLink meter must be published; errors: {0}; worker: {1}", string.Join("; ", session.Errors), worker.Output);
        session.Errors.Should().BeEmpty();
        PublishedValue pressReads = values.Last(v => v.Instrument == "hostlink.client.operation.duration"
            && v.Tags == "hostlink.command=RD,hostlink.link.name=press,hostlink.unit=0" && !v.Value.StartsWith("count=0 ", StringComparison.Ordinal));
        pressReads.Unit.Should().Be("s");
        pressReads.Value.Should().MatchRegex(@"^count=[1-9]\d* sum=\d", "reads were made in that interval").And.Contain("quantiles=0.5=");
        values.Should().Contain(v => v.Instrument == "hostlink.client.operation.duration" && v.Tags.StartsWith("error.type=timeout,", StringComparison.Ordinal)
            && v.Tags.Contains("hostlink.link.name=press", StringComparison.Ordinal) && v.Tags.Contains("hostlink.unit=5", StringComparison.Ordinal));
        values.Last(v => v.Instrument == "hostlink.client.connection.count" && v.Tags.Contains("hostlink.link.name=press", StringComparison.Ordinal))
            .Value.Should().EndWith("value=1", "the press link's connection is open");
    }

    private static bool Has(IReadOnlyList<PublishedValue> values, string kind, string instrument, string tag)
        => values.Any(v => v.Event == kind && v.Instrument == instrument && v.Tags.Contains(tag, StringComparison.Ordinal)
            && !v.Value.StartsWith("count=0 ", StringComparison.Ordinal));

    /// <summary>The last value of each time series, one line each, as the session received them.</summary>
    private static string Describe(IReadOnlyList<PublishedValue> values)
    {
        var text = new StringBuilder();
        foreach (PublishedValue v in values.GroupBy(v => (v.Instrument, v.Tags)).Select(g => g.Last()).OrderBy(v => v.Instrument, StringComparer.Ordinal).ThenBy(v => v.Tags, StringComparer.Ordinal))
        {
            text.AppendLine($"{v.Instrument} ({v.Unit}) [{v.Tags}] {v.Value}");
        }

        return text.ToString();
    }
}
