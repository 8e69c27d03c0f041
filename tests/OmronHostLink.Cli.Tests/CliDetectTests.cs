using System.Text;
using System.Text.Json;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// <c>detect</c> against simulated PLCs behind an emulated serial line whose PLC port has its own speed and format: the
/// line gives the host at other settings what a real one gives (garbage, parity errors the port ignores, silence).
/// </summary>
public sealed class CliDetectTests
{
    /// <summary>Each try's wait: long enough for a loaded machine to answer in process, short enough for the silent tries.</summary>
    private const string TryTimeout = "1s";

    [Theory]
    [InlineData(9600, "7E2", "9600,19200")]
    [InlineData(19200, "8N1", "19200,9600")]
    [InlineData(4800, "7E1", "9600,4800")]
    public async Task Detect_finds_the_speed_the_format_and_the_units_sending_only_TS_and_MM(int baud, string format, string speeds)
    {
        var log = new SimulatorFrameLog();
        var line = new EmulatedSerialLine(VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [0, 3, 17], FrameLog = log }), Settings(baud, format));

        CliResult r = await Cli.RunAsync(line.Transport, "detect", "--port", "/dev/ttyEMU0", "--speeds", speeds, "--units", "0-1,3,17-18", "--timeout", TryTimeout, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        JsonElement doc = r.Json();
        doc.GetProperty("baudRate").GetInt32().Should().Be(baud);
        doc.GetProperty("dataBits").GetInt32().Should().Be(format[0] - '0');
        doc.GetProperty("parity").GetString().Should().Be(format[1] switch { 'E' => "even", 'O' => "odd", _ => "none" });
        doc.GetProperty("localEcho").GetBoolean().Should().BeFalse();
        doc.GetProperty("units").EnumerateArray().Select(u => u.GetProperty("unit").GetInt32()).Should().Equal(0, 3, 17);
        doc.GetProperty("units").EnumerateArray().Should().OnlyContain(u => u.GetProperty("modelCode").GetString() == "30");

        // What the host put on the line, read at its own settings, and what the PLCs took from it: TS and MM only.
        line.HostTransmissions.Should().NotBeEmpty();
        line.HostTransmissions.Select(t => Header(t.Bytes)).Should().OnlyContain(h => h == "TS" || h == "MM", "detect sends nothing but TS, and MM once a unit answers");
        log.Frames.Where(f => f.FromHost).Select(f => f.Header).Should().OnlyContain(h => h == "TS" || h == "MM");
        log.Frames.Where(f => f.FromHost && f.Header == "MM").Select(f => f.Unit).Should().Equal(0, 3, 17);
    }

    [Fact]
    public async Task Stop_bits_are_said_to_be_indistinguishable_and_a_wrong_speed_and_format_are_named()
    {
        var line = new EmulatedSerialLine(VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [0] }), Settings(19200, "8N1"));

        CliResult r = await Cli.RunAsync(line.Transport, "detect", "--port", "/dev/ttyEMU0", "--speeds", "19200", "--units", "0", "--timeout", TryTimeout);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("Found: 19200 bps, 8 data bits, no parity, 1 stop bit (or 2)");
        r.Out.Should().Contain("The settings given, 9600 7E2 (Omron's default), get no answer: the PLC's port runs at 19200 8N1. The speed differs (19200 bps, not 9600), and the format differs (8 data bits and no parity, not 7 and even parity).");
        r.Out.Should().Contain("8N1 and 8N2 work alike");
        r.Out.Should().Contain("--port /dev/ttyEMU0 --baud 19200 --data-bits 8 --parity none --stop-bits 1 --unit 0");
    }

    [Fact]
    public async Task The_configuration_block_binds_to_the_client_settings()
    {
        var line = new EmulatedSerialLine(VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [3] }), Settings(38400, "7O2"));

        CliResult r = await Cli.RunAsync(line.Transport, "detect", "--port", "/dev/ttyEMU0", "--speeds", "38400", "--search-units", "3", "--units", "3", "--timeout", TryTimeout, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        var pairs = new List<KeyValuePair<string, string?>>();
        Flatten(r.Json().GetProperty("configuration"), null, pairs);
        var settings = new HostLinkClientSettings();
        settings.Read(pairs);
        settings.Validate().Should().BeEmpty();
        settings.UnitNumber.Should().Be(3);
        settings.Serial.BaudRate.Should().Be(38400);
        settings.Serial.DataBits.Should().Be(7);
        settings.Serial.Parity.Should().Be(SerialParity.Odd);
        settings.Serial.PortName.Should().Be("/dev/ttyEMU0");
    }

    [Fact]
    public async Task A_line_that_echoes_is_found_with_local_echo_and_units_are_read_through_the_echo()
    {
        var line = new EmulatedSerialLine(VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [0, 3] }), Settings(19200, "8N1"), twoWireEcho: true);

        CliResult r = await Cli.RunAsync(line.Transport, "detect", "--port", "/dev/ttyEMU0", "--speeds", "19200", "--units", "0-3", "--timeout", TryTimeout);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("our frame came back here too: the line echoes");
        r.Out.Should().Contain("Our own frames come back before each answer: the adapter is a 2-wire RS-485 one without echo suppression. Set LocalEcho (--local-echo)");
        r.Out.Should().Contain("Unit 00: CS/CJ (code 30)").And.Contain("Unit 03: CS/CJ (code 30)");
        r.Out.Should().Contain("--stop-bits 1 --unit 0 --local-echo").And.Contain("\"LocalEcho\": true");
    }

    [Fact]
    public async Task An_echo_with_no_plc_behind_it_is_said_in_words()
    {
        var line = new EmulatedSerialLine(VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [5] }), Settings(9600, "7E2"), twoWireEcho: true);

        CliResult r = await Cli.RunAsync(line.Transport, "detect", "--port", "/dev/ttyEMU0", "--speeds", "9600", "--formats", "7E2,8N1", "--timeout", TryTimeout);

        r.ExitCode.Should().Be(4, r.ToString());
        r.Out.Should().Contain("Our own frames came back at every setting, and nothing else: the adapter echoes what it sends (a 2-wire RS-485 adapter without echo suppression: set LocalEcho, --local-echo) and no PLC answered behind the echo.");
    }

    [Fact]
    public async Task Silence_is_said_in_words_with_what_to_check()
    {
        var line = new EmulatedSerialLine(VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [5] }), Settings(9600, "7E2"));

        CliResult r = await Cli.RunAsync(line.Transport, "detect", "--port", "/dev/ttyEMU0", "--speeds", "9600", "--formats", "7E2,8N1", "--timeout", "200ms");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Out.Should().Contain("Silence: no byte came back at any of the 2 settings tried (9600 7E2, 9600 8N1).");
        r.Out.Should().Contain("the TS went to unit 00 only; --search-units 0-31 tries every unit number");
        line.HostTransmissions.Select(t => Header(t.Bytes)).Should().OnlyContain(h => h == "TS");
    }

    private static string? Header(byte[] frame) => frame.Length >= 5 && frame[0] == '@' ? Encoding.ASCII.GetString(frame, 3, 2) : null;

    private static SerialLineSettings Settings(int baud, string format) => new()
    {
        PortName = "plc",
        BaudRate = baud,
        DataBits = format[0] - '0',
        Parity = format[1] switch { 'E' => SerialParity.Even, 'O' => SerialParity.Odd, _ => SerialParity.None },
        StopBits = format[2] == '1' ? SerialStopBits.One : SerialStopBits.Two,
    };

    private static void Flatten(JsonElement element, string? prefix, List<KeyValuePair<string, string?>> pairs)
    {
        foreach (JsonProperty p in element.EnumerateObject())
        {
            string key = prefix is null ? p.Name : prefix + ":" + p.Name;
            if (p.Value.ValueKind == JsonValueKind.Object)
            {
                Flatten(p.Value, key, pairs);
            }
            else
            {
                pairs.Add(new(key, p.Value.ValueKind == JsonValueKind.String ? p.Value.GetString() : p.Value.GetRawText()));
            }
        }
    }
}
