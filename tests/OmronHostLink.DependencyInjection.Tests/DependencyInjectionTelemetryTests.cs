using System.Diagnostics.Metrics;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Diagnostics.Metrics.Testing;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.DependencyInjection.Tests;

/// <summary>A client registered with <c>AddHostLinkClient</c> measures through the container's meter factory, under its registered name.</summary>
public sealed class DependencyInjectionTelemetryTests
{
    [Fact]
    public async Task A_client_from_the_container_records_through_the_containers_meter_factory_under_its_name()
    {
        await using var simulator = new TcpSimulatorHost(new VirtualPlc());
        await simulator.StartAsync();
        int port = simulator.EndPoint.Port;
        var services = new ServiceCollection().AddMetrics();
        foreach (string name in new[] { "press", "oven" })
        {
            services.AddHostLinkClient(name, o =>
            {
                o.Tcp.Host = "127.0.0.1";
                o.Tcp.Port = port;
                o.TurnaroundAllowance = Allowances.LosslessLine;
            });
        }
        await using ServiceProvider provider = services.BuildServiceProvider();
        using var durations = new MetricCollector<double>(provider.GetRequiredService<IMeterFactory>(), HostLinkTelemetry.MeterName, "hostlink.client.operation.duration");

        HostLinkClient press = provider.GetRequiredKeyedService<HostLinkClient>("press");
        HostLinkClient oven = provider.GetRequiredKeyedService<HostLinkClient>("oven");
        await press.ReadWordsAsync("D0", 1);
        await oven.ReadWordsAsync("D0", 1);

        press.LinkName.Should().Be("press");
        durations.GetMeasurementSnapshot().Select(m => (string?)m.Tags["hostlink.link.name"]).Should().Equal("press", "oven");
    }

    [Fact]
    public async Task The_default_client_is_named_by_its_transport()
    {
        await using var simulator = new TcpSimulatorHost(new VirtualPlc());
        await simulator.StartAsync();
        int port = simulator.EndPoint.Port;
        var services = new ServiceCollection().AddMetrics();
        services.AddHostLinkClient(o =>
        {
            o.Tcp.Host = "127.0.0.1";
            o.Tcp.Port = port;
            o.TurnaroundAllowance = Allowances.LosslessLine;
        });
        await using ServiceProvider provider = services.BuildServiceProvider();
        using var durations = new MetricCollector<double>(provider.GetRequiredService<IMeterFactory>(), HostLinkTelemetry.MeterName, "hostlink.client.operation.duration");

        await provider.GetRequiredService<HostLinkClient>().ReadWordsAsync("D0", 1);

        durations.LastMeasurement!.Tags["hostlink.link.name"].Should().Be($"127.0.0.1:{port}");
    }
}
