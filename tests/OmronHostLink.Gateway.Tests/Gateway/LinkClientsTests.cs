using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Transports;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>The worker's links become keyed clients of the DI package, every link key reaching the client.</summary>
public sealed class LinkClientsTests
{
    [Fact]
    public void A_tcp_link_maps_its_endpoint_connect_timeout_line_speed_and_client_settings()
    {
        LinkOptions link = BindLink(new()
        {
            ["Tcp"] = "127.0.0.1:9601",
            ["Tcp:ConnectTimeout"] = "3s",
            ["Serial:BaudRate"] = "19200",
            ["CommandSet"] = "Fins",
            ["TurnaroundAllowance"] = "450ms",
            ["ReadRetries"] = "4",
            ["WordOrder"] = "HighWordFirst",
        });
        HostLinkClientSettings settings = link.Client;

        (settings.Tcp.Host, settings.Tcp.Port, settings.Tcp.ConnectTimeout).Should().Be(("127.0.0.1", 9601, TimeSpan.FromSeconds(3)));
        settings.Serial.PortName.Should().BeNull();
        HostLinkClientOptions options = settings.ToClientOptions();
        options.LineTiming.Should().BeEquivalentTo(new LineTiming(19200, 11), "the line behind the server, 7E2");
        options.CommandSet.Should().Be(HostLinkCommandSet.Fins);
        options.TurnaroundAllowance.Should().Be(TimeSpan.FromMilliseconds(450));
        options.ReadRetries.Should().Be(4);
        options.WordOrder.Should().Be(WordOrder.HighWordFirst);
        options.WriteRetries.Should().Be(0, "a write whose answer was lost may have been carried out");
    }

    [Fact]
    public void A_serial_link_maps_every_line_setting()
    {
        var serial = new SerialLineSettings
        {
            PortName = "/dev/ttyUSB1",
            BaudRate = 38400,
            DataBits = 8,
            Parity = SerialParity.None,
            StopBits = SerialStopBits.One,
            Handshake = SerialHandshake.RequestToSend,
            DtrEnable = true,
        };

        HostLinkClientSettings settings = BindLink(new()
        {
            ["Serial:PortName"] = "/dev/ttyUSB1",
            ["Serial:BaudRate"] = "38400",
            ["Serial:DataBits"] = "8",
            ["Serial:Parity"] = "None",
            ["Serial:StopBits"] = "One",
            ["Serial:Handshake"] = "RequestToSend",
            ["Serial:DtrEnable"] = "true",
        }).Client;

        settings.Serial.ToLineSettings().Should().BeEquivalentTo(serial);
        settings.Tcp.Host.Should().BeNull();
    }

    [Fact]
    public async Task Each_enabled_link_is_a_keyed_client_named_after_it()
    {
        using IHost host = Build(new()
        {
            ["HostLink:Links:press:Tcp"] = "127.0.0.1:1",
            ["HostLink:Links:press:Groups:g:Address"] = "D0",
            ["HostLink:Links:oven:Tcp"] = "127.0.0.1:2",
            ["HostLink:Links:oven:Serial:BaudRate"] = "9600",
            ["HostLink:Links:oven:Groups:g:Address"] = "D0",
            ["HostLink:Links:spare:Enabled"] = "false",
        });

        HostLinkClient press = host.Services.GetRequiredKeyedService<HostLinkClient>("press");
        press.Description.Should().Contain("127.0.0.1:1");
        host.Services.GetRequiredKeyedService<HostLinkClient>("oven").Description.Should().Contain("127.0.0.1:2");
        host.Services.GetKeyedService<HostLinkClient>("spare").Should().BeNull("a disabled link has no client");
        await Task.CompletedTask;
    }

    [Fact]
    public async Task An_invalid_section_registers_no_client_and_fails_with_the_worker_messages_alone()
    {
        using IHost host = Build(new()
        {
            ["HostLink:Links:press:Tcp"] = "gateway",
            ["HostLink:Links:press:TurnaroundAllowance"] = "00:00:00",
            ["HostLink:Links:press:Groups:g:Address"] = "D0",
        });

        host.Services.GetKeyedService<HostLinkClient>("press").Should().BeNull();
        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        List<string> failures = error.Should().BeOfType<OptionsValidationException>().Subject.Failures.ToList();
        failures.Should().Contain(f => f.StartsWith("HostLink:Links:press:Tcp: 'gateway'", StringComparison.Ordinal));
        failures.Should().Contain(f => f.StartsWith("HostLink:Links:press:TurnaroundAllowance", StringComparison.Ordinal));
        failures.Should().OnlyContain(f => f.StartsWith("HostLink:Links:press", StringComparison.Ordinal), "each problem is reported once, by its worker key");
    }

    [Fact]
    public async Task A_line_speed_the_client_cannot_take_is_reported_by_its_worker_key()
    {
        using IHost host = Build(new()
        {
            ["HostLink:Links:press:Tcp"] = "127.0.0.1:1",
            ["HostLink:Links:press:Serial:BaudRate"] = "100000",
            ["HostLink:Links:press:Groups:g:Address"] = "D0",
        });

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        error.Should().BeOfType<OptionsValidationException>().Which.Failures.Should().ContainSingle()
            .Which.Should().StartWith("HostLink:Links:press:Serial:BaudRate: 100000 is not a standard rate (300, 600,");
    }

    /// <summary>The link <c>plc</c> bound from its keys (below <c>HostLink:Links:plc</c>) and a poll group.</summary>
    private static LinkOptions BindLink(Dictionary<string, string?> keys)
    {
        var configuration = new ConfigurationManager();
        configuration.AddInMemoryCollection(keys.ToDictionary(k => "HostLink:Links:plc:" + k.Key, k => k.Value));
        configuration.AddInMemoryCollection(new Dictionary<string, string?> { ["HostLink:Links:plc:Groups:g:Address"] = "D0" });
        var options = new GatewayOptions();
        LinkClients.Bind(configuration.GetSection(GatewayOptions.SectionName), options);
        return options.Links["plc"];
    }

    private static IHost Build(Dictionary<string, string?> config)
    {
        return TestGatewayHost.CreateBuilder(config).Build();
    }
}
