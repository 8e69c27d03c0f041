using System.Diagnostics;
using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.DependencyInjection.Tests;

/// <summary>Clients registered from JSON configuration and from code, resolved from the container, reading from simulators.</summary>
public sealed class HostLinkClientRegistrationTests
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task A_host_built_from_JSON_resolves_a_TCP_and_a_pty_client_by_name_and_reads_from_both_simulators()
    {
        var pressPlc = new VirtualPlc();
        pressPlc.WriteWords(PlcArea.Dm, 100, new ushort[] { 0x1234, 0x5678 });
        await using var pressSimulator = new TcpSimulatorHost(pressPlc);
        await pressSimulator.StartAsync();

        // The oven answers only as unit 3, and holds its values beyond C-mode's DM range: reading them proves the
        // unit number and the FINS protocol were taken from the file.
        var ovenPlc = new VirtualPlc(new VirtualPlcOptions { Units = new[] { 3 } });
        ovenPlc.WriteWords(PlcArea.Dm, 20000, new ushort[] { 0x0001, 0x0002 });
        await using SocatPtyPair pty = await SocatPtyPair.StartAsync();
        await using var ovenSimulator = new SerialSimulatorHost(ovenPlc, new SerialLineSettings { PortName = pty.PathB });
        await ovenSimulator.StartAsync();

        string json = $$"""
            {
              "HostLink": {
                "Clients": {
                  "press": {
                    "Tcp": "127.0.0.1:{{pressSimulator.EndPoint.Port}}",
                    "Serial": { "BaudRate": 115200, "DataBits": 8, "Parity": "None", "StopBits": 1 },
                    "TurnaroundAllowance": "5s"
                  },
                  "oven": {
                    "Serial": { "PortName": "{{pty.PathA}}", "BaudRate": 115200 },
                    "UnitNumber": 3,
                    "CommandSet": "Fins",
                    "WordOrder": "HighWordFirst",
                    "TurnaroundAllowance": "00:00:05"
                  }
                }
              }
            }
            """;
        await using JsonHost host = JsonHost.Build(json, (services, configuration) =>
            services.AddHostLinkClients(configuration.GetSection("HostLink:Clients")));
        await host.Host.StartAsync();

        HostLinkClient press = host.Services.GetRequiredKeyedService<HostLinkClient>("press");
        HostLinkClient oven = host.Services.GetRequiredKeyedService<HostLinkClient>("oven");

        (await press.ReadWordsAsync("D100", 2)).Should().Equal(0x1234, 0x5678);
        press.Description.Should().Be($"127.0.0.1:{pressSimulator.EndPoint.Port}");
        press.LineTiming.BaudRate.Should().Be(115200, "the serial side's speed behind a TCP server sets the deadlines");
        press.LineTiming.BitsPerCharacter.Should().Be(10, "8N1 is 1 start + 8 data + 1 stop bit");

        (await oven.ReadWordsAsync("D20000", 2)).Should().Equal(0x0001, 0x0002);
        (await oven.ReadInt32Async("D20000")).Should().Be(0x0001_0002, "the file sets HighWordFirst");
        oven.UnitNumber.Should().Be(3);
        oven.CommandSet.Should().Be(HostLinkCommandSet.Fins);
        oven.Description.Should().StartWith(pty.PathA + " 115200 7E2");
    }

    [Fact]
    public async Task FromKeyedServices_injects_the_named_client_and_there_is_no_default_client()
    {
        await using Simulated sim = await Simulated.StartAsync();
        await using JsonHost host = JsonHost.Build(sim.Json("line1"), (services, configuration) =>
        {
            services.AddHostLinkClient("line1", configuration.GetSection("HostLink:Clients:line1"));
            services.AddSingleton<Line1Reader>();
        });
        await host.Host.StartAsync();

        Line1Reader reader = host.Services.GetRequiredService<Line1Reader>();
        reader.Plc.Should().BeSameAs(host.Services.GetRequiredKeyedService<HostLinkClient>("line1"));
        (await reader.Plc.ReadWordAsync("D0")).Should().Be(Simulated.D0);
        host.Services.GetService<HostLinkClient>().Should().BeNull("naming clients never registers a default one");
    }

    [Fact]
    public async Task The_overload_without_a_name_registers_the_default_client()
    {
        await using Simulated sim = await Simulated.StartAsync();
        string json = $$"""{ "HostLink": { "Client": { "Tcp": { "Host": "127.0.0.1", "Port": {{sim.Port}}, "ConnectTimeout": "2s" }, "TurnaroundAllowance": "{{Allowances.LosslessLineText}}" } } }""";
        await using JsonHost host = JsonHost.Build(json, (services, configuration) =>
            services.AddHostLinkClient(configuration.GetSection("HostLink:Client")));
        await host.Host.StartAsync();

        HostLinkClient plc = host.Services.GetRequiredService<HostLinkClient>();
        (await plc.ReadWordAsync("D0")).Should().Be(Simulated.D0);
    }

    [Fact]
    public async Task A_client_set_in_code_reads_and_code_changes_apply_after_the_file()
    {
        await using Simulated sim = await Simulated.StartAsync();

        // The file points at a closed port; the code that follows it points at the simulator.
        string json = $$"""{ "HostLink": { "Clients": { "line1": { "Tcp": "127.0.0.1:1", "ReadRetries": 0, "TurnaroundAllowance": "{{Allowances.LosslessLineText}}" } } } }""";
        await using JsonHost host = JsonHost.Build(json, (services, configuration) =>
        {
            services.AddHostLinkClient("line1", configuration.GetSection("HostLink:Clients:line1"), o => o.Tcp.Port = sim.Port);
            services.AddHostLinkClient("line2", o =>
            {
                o.Tcp.Host = "127.0.0.1";
                o.Tcp.Port = sim.Port;
                o.TurnaroundAllowance = Allowances.LosslessLine;
                o.CommandSet = HostLinkCommandSet.Fins;
            });
        });
        await host.Host.StartAsync();

        (await host.Services.GetRequiredKeyedService<HostLinkClient>("line1").ReadWordAsync("D0")).Should().Be(Simulated.D0);
        HostLinkClient line2 = host.Services.GetRequiredKeyedService<HostLinkClient>("line2");
        line2.CommandSet.Should().Be(HostLinkCommandSet.Fins);
        (await line2.ReadWordAsync("D0")).Should().Be(Simulated.D0);
    }

    [Fact]
    public async Task The_client_is_one_instance_that_logs_through_the_container_and_closes_with_it()
    {
        await using Simulated sim = await Simulated.StartAsync();
        JsonHost host = JsonHost.Build(sim.Json("line1"), (services, configuration) =>
            services.AddHostLinkClients(configuration.GetSection("HostLink:Clients")));
        try
        {
            await host.Host.StartAsync();
            sim.Host.AcceptedConnections.Should().Be(0, "a client connects on its first exchange, not when the host starts");

            HostLinkClient first = host.Services.GetRequiredKeyedService<HostLinkClient>("line1");
            first.Should().BeSameAs(host.Services.GetRequiredKeyedService<HostLinkClient>("line1"));
            (await first.ReadWordAsync("D0")).Should().Be(Simulated.D0);
            sim.Host.ActiveSessions.Should().Be(1);
            host.Logs.Entries.Should().Contain(e => e.Category.StartsWith("OmronHostLink", StringComparison.Ordinal) && e.Level == LogLevel.Debug,
                "the library logs each transaction at Debug through the host's logger factory");
        }
        finally
        {
            await host.DisposeAsync();
        }

        await Eventually.UntilAsync(() => sim.Host.ActiveSessions == 0, "the simulator has no session left", patience: Patience);
        sim.Host.ActiveSessions.Should().Be(0, "disposing the container closes the client's connection");
    }

    [Fact]
    public void A_name_registered_twice_is_refused()
    {
        var services = new ServiceCollection();
        services.AddHostLinkClient("line1", o => o.Serial.PortName = "/dev/ttyUSB0");

        FluentActions.Invoking(() => services.AddHostLinkClient("line1", o => o.Serial.PortName = "/dev/ttyUSB1"))
            .Should().Throw<InvalidOperationException>().WithMessage("A Host Link client named 'line1' is registered already.");
        FluentActions.Invoking(() => services.AddHostLinkClient("  ", o => o.Serial.PortName = "/dev/ttyUSB1"))
            .Should().Throw<ArgumentException>().WithParameterName("name");
    }

    [Fact]
    public void A_clients_section_with_no_client_is_refused_naming_it()
    {
        IConfiguration configuration = new ConfigurationBuilder()
            .AddInMemoryCollection(new Dictionary<string, string?> { ["HostLink:Other"] = "x" })
            .Build();

        FluentActions.Invoking(() => new ServiceCollection().AddHostLinkClients(configuration.GetSection("HostLink:Clients")))
            .Should().Throw<InvalidOperationException>().WithMessage("Configuration section 'HostLink:Clients' holds no Host Link client*");
    }

    /// <summary>A consumer that takes a named client by injection.</summary>
    private sealed class Line1Reader([FromKeyedServices("line1")] HostLinkClient plc)
    {
        public HostLinkClient Plc { get; } = plc;
    }

    /// <summary>A simulator on TCP loopback holding <see cref="D0"/> in D0.</summary>
    private sealed class Simulated : IAsyncDisposable
    {
        public const ushort D0 = 0xBEEF;

        private Simulated(TcpSimulatorHost host) => Host = host;

        public TcpSimulatorHost Host { get; }

        public int Port => Host.EndPoint.Port;

        public static async Task<Simulated> StartAsync()
        {
            var plc = new VirtualPlc();
            plc.WriteWord(PlcArea.Dm, 0, D0);
            var host = new TcpSimulatorHost(plc);
            await host.StartAsync();
            return new Simulated(host);
        }

        public string Json(string name) => $$"""{ "HostLink": { "Clients": { "{{name}}": { "Tcp": "127.0.0.1:{{Port}}", "TurnaroundAllowance": "{{Allowances.LosslessLineText}}" } } } }""";

        public ValueTask DisposeAsync() => Host.DisposeAsync();
    }
}
