using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway;
using OpenTelemetry.Metrics;
using OpenTelemetry.Trace;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>The opt-in OpenTelemetry export: off by default, on by name, an unknown name refused at start.</summary>
public sealed class TelemetryExportTests
{
    [Theory]
    [InlineData(null, false)]
    [InlineData("None", false)]
    [InlineData("console", true)]
    [InlineData("Otlp", true)]
    public void The_exporter_is_added_only_when_named(string? exporter, bool exported)
    {
        using IHost host = Build(exporter);
        (host.Services.GetService<MeterProvider>() is not null).Should().Be(exported);
        (host.Services.GetService<TracerProvider>() is not null).Should().Be(exported, "the library's spans are exported with its metrics");
    }

    [Fact]
    public async Task An_unknown_exporter_fails_at_start_naming_the_key()
    {
        using IHost host = Build("Prometheus");
        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());
        error.Should().BeOfType<OptionsValidationException>().Which.Failures.Should().Equal("OpenTelemetry:Exporter 'Prometheus' is not None, Console or Otlp.");
    }

    private static IHost Build(string? exporter)
    {
        return TestGatewayHost.CreateBuilder(new Dictionary<string, string?>
        {
            ["HostLink:Links:plc:Tcp"] = "127.0.0.1:1",
            ["HostLink:Links:plc:Groups:g:Address"] = "D0",
            ["OpenTelemetry:Exporter"] = exporter,
        }).Build();
    }
}
