using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;
using OmronHostLink.DependencyInjection;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.DependencyInjection.Tests;

/// <summary>Bad configuration stops the host at start, with every problem named by its configuration key.</summary>
public sealed class HostLinkConfigurationValidationTests
{
    private const string Line1 = "HostLink:Clients:line1";

    private static readonly Action<IServiceCollection, IConfiguration> AllClients =
        (services, configuration) => services.AddHostLinkClients(configuration.GetSection("HostLink:Clients"));

    /// <summary>A configuration file with one client, line1, whose section holds <paramref name="body"/>.</summary>
    private static string OneClient(string body) => $$"""{ "HostLink": { "Clients": { "line1": { {{body}} } } } }""";

    [Fact]
    public async Task Several_bad_keys_fail_at_start_each_named_by_its_path_and_nothing_is_sent()
    {
        await using var simulator = new TcpSimulatorHost(new VirtualPlc());
        await simulator.StartAsync();
        string json = OneClient($$"""
            "Tcp": "127.0.0.1:{{simulator.EndPoint.Port}}",
            "Serial": { "BaudRate": 12345, "DataBits": 6 },
            "UnitNumber": 40,
            "ReadRetries": -1,
            "CommandSet": "Finz",
            "TurnaroundAllowance": "abc",
            "LocalEcho": "yes",
            "FinsResponseWait": 16
            """);

        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(json, AllClients);

        failures.Should().BeEquivalentTo(
            $"{Line1}:Serial:BaudRate: 12345 is not a standard rate (300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400)",
            $"{Line1}:Serial:DataBits: 6 is not 7 or 8",
            $"{Line1}:UnitNumber: 40 is not a unit number (0-31)",
            $"{Line1}:ReadRetries: -1 is not 0-10",
            $"{Line1}:CommandSet: 'Finz' is not one of CMode, Fins",
            $"{Line1}:TurnaroundAllowance: 'abc' is not a duration; write 300ms, 1.5s, 2m or 00:00:00.300",
            $"{Line1}:LocalEcho: 'yes' is not true or false",
            $"{Line1}:FinsResponseWait: 16 is not 0-15 (units of 10 ms)");
        simulator.AcceptedConnections.Should().Be(0, "a client with bad settings is never created");
    }

    [Fact]
    public async Task An_unknown_model_is_an_error_naming_the_key()
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(
            OneClient("""  "Tcp": "127.0.0.1:9", "Model": "CPM9" """), AllClients);

        failures.Should().ContainSingle().Which.Should().StartWith($"{Line1}:Model: 'CPM9' is not a known PLC model; use one of C200H, ")
            .And.EndWith(", or auto to ask the PLC (MM)");
    }

    [Fact]
    public async Task A_misspelt_protocol_is_an_error_naming_the_key_not_a_dropped_link()
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(
            OneClient("""  "Tcp": "127.0.0.1:9", "CommandSet": "Finz" """), AllClients);

        failures.Should().Equal($"{Line1}:CommandSet: 'Finz' is not one of CMode, Fins");
    }

    [Fact]
    public async Task Unknown_keys_are_named_with_the_key_meant()
    {
        string json = OneClient("""
            "Serial": { "PortName": "/dev/ttyUSB0", "BaudRat": 9600 },
            "TurnaroundAlowance": "300ms",
            "BaudRate": 19200,
            "Unit": 2,
            "Colour": "red"
            """);

        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(json, AllClients);

        failures.Should().BeEquivalentTo(
            $"{Line1}:Serial:BaudRat: not a serial line setting; did you mean Serial:BaudRate?",
            $"{Line1}:TurnaroundAlowance: not a Host Link client setting; did you mean TurnaroundAllowance?",
            $"{Line1}:BaudRate: not a Host Link client setting; did you mean Serial:BaudRate?",
            $"{Line1}:Unit: not a Host Link client setting; did you mean UnitNumber?",
            $"{Line1}:Colour: not a Host Link client setting (known: Serial, Tcp, UnitNumber, CommandSet, TurnaroundAllowance, ReadRetries, WriteRetries, WordOrder, LocalEcho, VerifyAnswers, FinsResponseWait, AllowReadModifyWriteBits, UseCompoundRead, Model, HostLinkCompatibleMode, SendInterval, TraceFile, UnitSendIntervals)");
    }

    [Theory]
    [InlineData("300", "'300' has no unit; write 300ms, 300s or 300m (or 00:00:00.3 for 300ms)")]
    [InlineData("0.5", "'0.5' has no unit; write 0.5ms, 0.5s or 0.5m (or 00:00:00.0005 for 0.5ms)")]
    [InlineData("abc", "'abc' is not a duration; write 300ms, 1.5s, 2m or 00:00:00.300")]
    [InlineData("300 parsecs", "'300 parsecs' is not a duration; write 300ms, 1.5s, 2m or 00:00:00.300")]
    [InlineData("-1s", "'-1s' is not a duration; write 300ms, 1.5s, 2m or 00:00:00.300")]
    [InlineData("00:00:xx", "'00:00:xx' is not a duration; write 300ms, 1.5s, 2m or 00:00:00.300")]
    [InlineData("0ms", "00:00:00 is not more than 0 and at most 1 minute")]
    [InlineData("2m", "00:02:00 is not more than 0 and at most 1 minute")]
    [InlineData("", "is empty; write a value, or remove the key to use the default")]
    public async Task A_bad_duration_is_named(string text, string message)
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(
            OneClient($$"""  "Tcp": "127.0.0.1:9", "TurnaroundAllowance": "{{text}}" """), AllClients);

        failures.Should().Equal($"{Line1}:TurnaroundAllowance: {message}");
    }

    [Theory]
    [InlineData("300ms", 300)]
    [InlineData("1.5s", 1500)]
    [InlineData("2s", 2000)]
    [InlineData(" 250 ms ", 250)]
    [InlineData("00:00:00.300", 300)]
    [InlineData("00:00:01", 1000)]
    [InlineData("0.5m", 30_000)]
    public async Task Durations_are_read_in_the_TimeSpan_form_and_with_ms_s_m_units(string text, int milliseconds)
    {
        await using JsonHost host = JsonHost.Build(
            OneClient($$"""  "Tcp": { "Host": "127.0.0.1", "Port": 9, "ConnectTimeout": "{{text}}" }, "TurnaroundAllowance": "{{text}}" """), AllClients);
        await host.Host.StartAsync();

        HostLinkClientSettings settings = host.Services.GetRequiredService<IOptionsMonitor<HostLinkClientSettings>>().Get("line1");
        settings.TurnaroundAllowance.Should().Be(TimeSpan.FromMilliseconds(milliseconds));
        settings.Tcp.ConnectTimeout.Should().Be(TimeSpan.FromMilliseconds(milliseconds));
    }

    [Fact]
    public async Task Both_a_serial_port_and_a_TCP_server_are_refused()
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(
            OneClient("""  "Serial": { "PortName": "/dev/ttyUSB0" }, "Tcp": "127.0.0.1:4001" """), AllClients);

        failures.Should().Equal($"{Line1}:Tcp: cannot be combined with Serial:PortName; a client uses either a local serial port or a serial-device server");
    }

    [Fact]
    public async Task Both_links_are_refused_even_when_the_TCP_one_cannot_be_read()
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(
            OneClient("""  "Serial": { "PortName": "/dev/ttyUSB0" }, "Tcp": "plc" """), AllClients);

        failures.Should().BeEquivalentTo(
            $"{Line1}:Tcp: 'plc' is not host:port (e.g. 192.0.2.10:4001), or write a section with Host and Port",
            $"{Line1}:Tcp: cannot be combined with Serial:PortName; a client uses either a local serial port or a serial-device server");
    }

    [Fact]
    public async Task A_client_with_no_link_is_refused()
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(
            OneClient("""  "Serial": { "BaudRate": 19200 }, "UnitNumber": 1 """), AllClients);

        failures.Should().Equal($"{Line1}: no link is set; write Serial:PortName (a serial port such as COM3 or /dev/ttyUSB0) or Tcp (host:port of a serial-device server)");
    }

    [Theory]
    [InlineData("\"Tcp\": \"plc\"", "Tcp: 'plc' is not host:port (e.g. 192.0.2.10:4001), or write a section with Host and Port")]
    [InlineData("\"Tcp\": \"plc:70000\"", "Tcp: 'plc:70000': the port '70000' is not a number 1-65535")]
    [InlineData("\"Tcp\": \"fd00::5:4001\"", "Tcp: 'fd00::5:4001': write an IPv6 address in brackets, e.g. [fd00::5]:4001")]
    [InlineData("\"Tcp\": { \"Host\": \"plc\" }", "Tcp:Port: is missing; write the serial-device server's TCP port (1-65535)")]
    [InlineData("\"Tcp\": { \"Port\": 4001 }", "Tcp:Host: is missing; write the serial-device server's host name or address")]
    [InlineData("\"Tcp\": { \"Host\": \"plc\", \"Port\": 0 }", "Tcp:Port: 0 is not a TCP port (1-65535)")]
    [InlineData("\"Tcp\": { \"Host\": \"plc\", \"Port\": \"x\" }", "Tcp:Port: 'x' is not a whole number")]
    [InlineData("\"Tcp\": \"plc:4001\", \"Serial\": { \"Handshake\": \"RequestToSend\" }", "Serial:Handshake: applies to a local serial port; the serial-device server's own settings control it")]
    [InlineData("\"Serial\": \"COM3\"", "Serial: expects a section (PortName, BaudRate, DataBits, Parity, StopBits, Handshake, DtrEnable, RtsEnable), not a value")]
    [InlineData("\"Tcp\": \"plc:4001\", \"UnitNumber\": { \"Value\": 1 }", "UnitNumber: expects a value, not a section")]
    [InlineData("\"Serial\": { \"PortName\": \"COM3\", \"Parity\": \"Mark\" }", "Serial:Parity: 'Mark' is not one of None, Even, Odd")]
    [InlineData("\"Serial\": { \"PortName\": \"COM3\", \"StopBits\": 1.5 }", "Serial:StopBits: '1.5' is not one of One, Two, 1, 2")]
    [InlineData("\"Serial\": { \"PortName\": \"COM3\", \"Handshake\": \"RequestToSend\", \"RtsEnable\": true }", "Serial:RtsEnable: cannot be true with Handshake RequestToSend: the driver controls RTS")]
    public async Task A_bad_link_setting_is_named(string body, string failure)
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(OneClient(body), AllClients);

        failures.Should().Equal($"{Line1}:{failure}");
    }

    [Fact]
    public async Task Problems_in_two_clients_are_reported_together()
    {
        string json = """
            {
              "HostLink": {
                "Clients": {
                  "line1": { "Tcp": "127.0.0.1:9", "CommandSet": "Finz" },
                  "line2": { "Serial": { "PortName": "COM3", "DataBits": 9 } }
                }
              }
            }
            """;

        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(json, AllClients);

        failures.Should().BeEquivalentTo(
            $"{Line1}:CommandSet: 'Finz' is not one of CMode, Fins",
            "HostLink:Clients:line2:Serial:DataBits: 9 is not 7 or 8");
    }

    [Fact]
    public async Task A_missing_client_section_is_named()
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(
            OneClient("""  "Tcp": "127.0.0.1:9" """),
            (services, configuration) => services.AddHostLinkClient("line9", configuration.GetSection("HostLink:Clients:line9")));

        failures.Should().Equal("HostLink:Clients:line9: the section is missing or empty; check the client's name and write Serial:PortName or Tcp in it");
    }

    [Fact]
    public async Task Settings_made_in_code_are_named_by_the_client()
    {
        IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync("{}", (services, _) =>
        {
            services.AddHostLinkClient("press", o =>
            {
                o.Serial.PortName = "/dev/ttyUSB0";
                o.UnitNumber = 99;
                o.TurnaroundAllowance = TimeSpan.FromMinutes(2);
            });
            services.AddHostLinkClient(_ => { });
        });

        failures.Should().BeEquivalentTo(
            "Host Link client \"press\": UnitNumber: 99 is not a unit number (0-31)",
            "Host Link client \"press\": TurnaroundAllowance: 00:02:00 is not more than 0 and at most 1 minute",
            "The default Host Link client: no link is set; write Serial:PortName (a serial port such as COM3 or /dev/ttyUSB0) or Tcp (host:port of a serial-device server)");
    }

    [Fact]
    public void Without_a_started_host_resolving_a_badly_configured_client_throws_naming_the_key()
    {
        IConfiguration configuration = new ConfigurationBuilder()
            .AddInMemoryCollection(new Dictionary<string, string?>
            {
                ["HostLink:Clients:line1:Tcp"] = "127.0.0.1:9",
                ["HostLink:Clients:line1:WordOrder"] = "BigEndian",
            })
            .Build();
        using ServiceProvider provider = new ServiceCollection().AddHostLinkClients(configuration.GetSection("HostLink:Clients")).BuildServiceProvider();

        FluentActions.Invoking(() => provider.GetRequiredKeyedService<HostLinkClient>("line1"))
            .Should().Throw<OptionsValidationException>()
            .Which.Failures.Should().Equal($"{Line1}:WordOrder: 'BigEndian' is not one of LowWordFirst, HighWordFirst");
    }

    [Fact]
    public async Task Names_in_any_case_and_stop_bits_as_digits_are_read()
    {
        await using JsonHost host = JsonHost.Build(
            OneClient("""
                "serial": { "portname": "/dev/ttyUSB0", "parity": "odd", "stopBits": "1", "dataBits": 8, "handshake": "xonxoff", "dtrEnable": "True" },
                "commandSet": "fins", "wordOrder": "highwordfirst", "allowReadModifyWriteBits": true, "writeRetries": 1
                """),
            AllClients);
        await host.Host.StartAsync();

        HostLinkClientSettings s = host.Services.GetRequiredService<IOptionsMonitor<HostLinkClientSettings>>().Get("line1");
        s.Serial.PortName.Should().Be("/dev/ttyUSB0");
        s.Serial.Parity.Should().Be(SerialParity.Odd);
        s.Serial.StopBits.Should().Be(SerialStopBits.One);
        s.Serial.DataBits.Should().Be(8);
        s.Serial.Handshake.Should().Be(SerialHandshake.XOnXOff);
        s.Serial.DtrEnable.Should().BeTrue();
        s.CommandSet.Should().Be(HostLinkCommandSet.Fins);
        s.WordOrder.Should().Be(WordOrder.HighWordFirst);
        s.AllowReadModifyWriteBits.Should().BeTrue();
        s.WriteRetries.Should().Be(1);
        s.UnitNumber.Should().BeNull("an unset key keeps the library's default");
    }
}
