using System.CommandLine;
using System.Globalization;
using System.Text.Json;
using OmronHostLink.Cli.Detection;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Commands;

/// <summary>
/// <c>detect</c>: finds a serial line's speed and format and the units on it with TS probes alone (and MM once a unit
/// answers), says in plain words what it found or why nothing answered, and prints the settings as the console's flags
/// and as a configuration block.
/// </summary>
internal static class DetectCommand
{
    /// <summary>The speeds tried after the given one, fastest first: a try at a fast speed costs the least.</summary>
    private static readonly int[] Speeds = [115200, 57600, 38400, 19200, 9600, 4800, 2400, 1200];

    public static Command Create(CliContext context)
    {
        var command = new Command("detect", "Find a serial line's speed, format and units: TS at the usual speeds (1200-115200) and formats (7E2, 8N1, 7O2, 8E1, 8O1, 7N2), the given settings first, then the fastest; MM names each unit that answers. Sends nothing else. Says in words what it found or why nothing answers, and prints the settings as flags and configuration.");
        var line = new LineSettingsOptions("the settings tried first, the ones configured now");
        var port = new Option<string?>("--port") { Description = "Serial port: COM3, /dev/ttyUSB0, or any device path.", HelpName = "name" };
        var tcp = new Option<string?>("--tcp") { Description = "A serial-device server as host:port: its serial settings are its own configuration, so only the units are looked for (the line settings below set the deadlines).", HelpName = "host:port" };
        var speeds = new Option<string?>("--speeds") { Description = $"Speeds to try, e.g. 9600,19200 (default {string.Join(",", Speeds)}).", HelpName = "list" };
        var formats = new Option<string?>("--formats") { Description = $"Formats to try, e.g. 7E2,8N1 (default {string.Join(",", LineFormat.Usual)}).", HelpName = "list" };
        var searchUnits = new Option<string>("--search-units") { Description = "Unit numbers the TS goes to at each setting while the settings are unknown: a PLC at another number stays silent at every setting (0-31 tries every number, 32 times slower).", DefaultValueFactory = _ => "0", HelpName = "list" };
        var units = new Option<string>("--units") { Description = $"Unit numbers to look for once the settings are found: 0-{SettingRules.MaxUnitNumber}, 0,1,5 or 0-3,7.", DefaultValueFactory = _ => $"0-{SettingRules.MaxUnitNumber}", HelpName = "list" };
        Option<TimeSpan?> timeout = Durations.Option("--timeout", "Time a unit may take to start answering a TS (its wire time is added); each try waits no longer.", TimeSpan.FromMilliseconds(100), TimeSpan.FromMilliseconds(1), TimeSpan.FromMinutes(1));
        Option<bool> json = CliContext.JsonOption();
        command.Add(port);
        command.Add(tcp);
        line.AddTo(command);
        foreach (Option o in new Option[] { speeds, formats, searchUnits, units, timeout, json })
        {
            command.Add(o);
        }

        context.SetAction(command, json, async (parse, output, ct) =>
        {
            string? portName = parse.GetValue(port);
            string? tcpText = parse.GetValue(tcp);
            if (string.IsNullOrWhiteSpace(portName) == string.IsNullOrWhiteSpace(tcpText))
            {
                throw new UsageException(portName is null && tcpText is null
                    ? "Say which line to look at: give --port <name> for a serial port or --tcp <host:port> for a serial-device server."
                    : "Give either --port or --tcp, not both.");
            }

            SerialLineSettings given = line.Settings(parse, portName ?? "tcp");
            IReadOnlyList<int> searchList = Numbers.ParseUnits(parse.GetValue(searchUnits)!, "--search-units");
            IReadOnlyList<int> unitList = Numbers.ParseUnits(parse.GetValue(units)!, "--units");
            TimeSpan turnaround = parse.GetValue(timeout) ?? TimeSpan.FromMilliseconds(100);
            bool overTcp = tcpText is not null;
            Func<SerialLineSettings, IHostLinkTransport> open;
            string where;
            if (overTcp)
            {
                (string host, int tcpPort) = ConnectionOptions.ParseEndpoint(tcpText!, "--tcp");
                open = _ => new TcpTransport(host, tcpPort, TimeSpan.FromSeconds(5));
                where = $"{host}:{tcpPort}";
            }
            else
            {
                open = context.SerialPorts;
                where = portName!;
            }

            var first = (given.BaudRate, LineFormat.Of(given));
            List<(int Baud, LineFormat Format)> candidates = overTcp ? [first] : Candidates(first, ParseSpeeds(parse.GetValue(speeds)), ParseFormats(parse.GetValue(formats)));
            var detector = new LineDetector(open, where, turnaround);
            output.Note(overTcp
                ? $"Looking for units on {where} (a serial-device server: its serial settings are its own; TS to {UnitWords(searchList)})..."
                : $"Looking for the settings of {where}: TS to {UnitWords(searchList)} at {candidates.Count} setting{(candidates.Count == 1 ? "" : "s")}, {first.BaudRate} {first.Item2} first, then the fastest...");
            LineDetector.Outcome outcome = await detector.SearchAsync(candidates, searchList, t => Report(output, t), ct).ConfigureAwait(false);
            List<string> diagnosis = LineDiagnosis.Describe(outcome, first, searchList, overTcp);

            var found = new List<(int Unit, PlcModel? Model, string? Error)>();
            SerialLineSettings? settings = null;
            if (outcome.Found is { } hit)
            {
                settings = hit.At(where);
                bool echo = outcome.Echo == true;
                output.Line($"Found: {hit.Baud} bps, {hit.Format.Words}{(overTcp ? "" : $" (or {(int)hit.Format.OtherStopBits.StopBits})")}{(echo ? ", with echo" : "")}: unit {hit.Unit:D2} answered TS{(hit.RoundTrip is { } rtt ? $" in {Milliseconds(rtt)}" : "")}.");
                foreach (string sentence in diagnosis)
                {
                    output.Line("  " + sentence);
                }

                output.Note($"Looking for {UnitWords(unitList)} at {hit.Settings}...");
                await using HostLinkClient client = HostLinkClient.Create(open(settings), new HostLinkClientOptions
                {
                    TurnaroundAllowance = turnaround,
                    ReadRetries = 1,
                    LocalEcho = echo,
                    LineTiming = new LineTiming(settings.BaudRate, settings.BitsPerCharacter),
                });
                if (output.Verbose)
                {
                    client.FrameObserver = output.FrameTrace();
                }

                foreach (int unit in unitList)
                {
                    HostLinkUnit plc = client.Unit(unit);
                    if (await plc.ProbeAsync(cancellationToken: ct).ConfigureAwait(false) is null)
                    {
                        continue;
                    }

                    try
                    {
                        PlcModel model = await plc.ReadModelAsync(ct).ConfigureAwait(false);
                        found.Add((unit, model, null));
                        output.Line($"Unit {unit:D2}: {model}");
                    }
                    catch (Exception e) when (e is HostLinkEndCodeException or HostLinkTimeoutException or HostLinkFrameException)
                    {
                        found.Add((unit, null, CliContext.Describe(e)));
                        output.Line($"Unit {unit:D2}: answers TS; MM: {CliContext.Describe(e)}");
                    }
                }

                output.Line(found.Count == 1 ? "1 unit answers." : $"{found.Count} units answer.");
                if (found.Count > 0)
                {
                    output.Line();
                    output.Line("Console flags:");
                    output.Line("  " + Flags(settings, overTcp ? tcpText : null, echo, found[0].Unit));
                    output.Line("Configuration (a client section: appsettings.json, the gateway's link, HostLink:Clients):");
                    foreach (string configLine in Configuration(settings, overTcp ? tcpText : null, echo, found[0].Unit).Split('\n'))
                    {
                        output.Line("  " + configLine);
                    }
                }
            }
            else
            {
                output.Line($"Nothing answered ({candidates.Count * searchList.Count} tries in {Durations.Format(outcome.Elapsed)}).");
                foreach (string sentence in diagnosis)
                {
                    output.Line("  " + sentence);
                }
            }

            output.Note($"Done in {Durations.Format(outcome.Elapsed)} of searching.");
            if (output.IsJson)
            {
                output.Result(_ => { }, j => WriteJson(j, where, overTcp ? tcpText : null, outcome, settings, found, diagnosis));
            }

            if (found.Count == 0)
            {
                if (output.IsJson)
                {
                    output.Fail(diagnosis.FirstOrDefault() ?? "Nothing answered.");
                }

                return ExitCodes.Communication;
            }

            return ExitCodes.Success;
        });
        return command;
    }

    /// <summary>The settings to try, in order: the given one, then each speed fastest first in each format, one of each pair a receiver cannot tell apart.</summary>
    internal static List<(int Baud, LineFormat Format)> Candidates((int Baud, LineFormat Format) first, IReadOnlyList<int> speeds, IReadOnlyList<LineFormat> formats)
    {
        var list = new List<(int Baud, LineFormat Format)> { first };
        foreach (int speed in speeds)
        {
            foreach (LineFormat format in formats)
            {
                if (!list.Any(c => c.Baud == speed && c.Format.SameOnTheWire(format)))
                {
                    list.Add((speed, format));
                }
            }
        }

        return list;
    }

    /// <summary>The console flags for the settings found.</summary>
    internal static string Flags(SerialLineSettings settings, string? tcp, bool echo, int unit)
    {
        string where = tcp is null ? $"--port {settings.PortName}" : $"--tcp {tcp}";
        string parity = settings.Parity.ToString().ToLowerInvariant();
        return $"{where} --baud {settings.BaudRate} --data-bits {settings.DataBits} --parity {parity} --stop-bits {(int)settings.StopBits} --unit {unit}{(echo ? " --local-echo" : "")}";
    }

    /// <summary>A client section with the settings found, as configuration binds <see cref="HostLinkClientSettings"/>.</summary>
    internal static string Configuration(SerialLineSettings settings, string? tcp, bool echo, int unit)
    {
        var buffer = new System.Buffers.ArrayBufferWriter<byte>();
        using (var j = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
        {
            j.WriteStartObject();
            if (tcp is not null)
            {
                j.WriteString("Tcp", tcp);
            }

            j.WriteStartObject("Serial");
            if (tcp is null)
            {
                j.WriteString("PortName", settings.PortName);
            }

            j.WriteNumber("BaudRate", settings.BaudRate);
            j.WriteNumber("DataBits", settings.DataBits);
            j.WriteString("Parity", settings.Parity.ToString());
            j.WriteString("StopBits", settings.StopBits.ToString());
            j.WriteEndObject();
            j.WriteNumber("UnitNumber", unit);
            j.WriteBoolean("LocalEcho", echo);
            j.WriteEndObject();
        }

        return System.Text.Encoding.UTF8.GetString(buffer.WrittenSpan).Replace("\r\n", "\n", StringComparison.Ordinal);
    }

    private static void Report(OutputWriter output, ProbeTry t)
    {
        if (output.IsJson)
        {
            return;
        }

        output.Line($"  {t.Settings,-11} unit {t.Unit:D2}: {Words(t)}");
    }

    /// <summary>One try in words.</summary>
    internal static string Words(ProbeTry t)
    {
        ProbeReply r = t.Reply;
        if (r.Silent)
        {
            return $"silence ({Milliseconds(t.Elapsed)}){(t.Confirming ? ": the copy before was the PLC's answer, not an echo" : "")}";
        }

        var parts = new List<string>();
        if (r.Copies > 0)
        {
            parts.Add(t.Confirming
                ? r.Copies == 1 ? "our frame came back here too: the line echoes" : "our frame came back twice"
                : r.Copies == 1 ? $"our frame came back{(t.RoundTrip is { } rtt ? $" in {Milliseconds(rtt)}" : "")}" : $"our frame came back twice: the echo, then the answer{(t.RoundTrip is { } rtt2 ? $" in {Milliseconds(rtt2)}" : "")}");
        }

        if (r.EndCode is { } code)
        {
            parts.Add($"an answer with end code {code}");
        }

        if (r.Ic)
        {
            parts.Add("an IC answer (TS not taken)");
        }

        if (r.BadFcs > 0)
        {
            parts.Add($"{r.BadFcs} frame{(r.BadFcs == 1 ? "" : "s")} with a wrong FCS");
        }

        if (r.OtherFrames > 0)
        {
            parts.Add($"{r.OtherFrames} other frame{(r.OtherFrames == 1 ? "" : "s")}");
        }

        if (r.Unframed > 0)
        {
            parts.Add($"{r.Unframed} byte{(r.Unframed == 1 ? "" : "s")} that do not frame: \"{r.Sample()}\"");
        }

        return string.Join("; ", parts);
    }

    private static void WriteJson(Utf8JsonWriter j, string where, string? tcp, LineDetector.Outcome outcome, SerialLineSettings? settings, List<(int Unit, PlcModel? Model, string? Error)> found, List<string> diagnosis)
    {
        j.WriteStartObject();
        j.WriteString(tcp is null ? "port" : "tcp", where);
        j.WriteBoolean("found", settings is not null);
        if (settings is null)
        {
            j.WriteNull("baudRate");
            j.WriteNull("format");
        }
        else
        {
            j.WriteNumber("baudRate", settings.BaudRate);
            j.WriteString("format", LineFormat.Of(settings).ToString());
            j.WriteNumber("dataBits", settings.DataBits);
            j.WriteString("parity", settings.Parity.ToString().ToLowerInvariant());
            j.WriteNumber("stopBits", (int)settings.StopBits);
        }

        if (outcome.Echo is { } echo)
        {
            j.WriteBoolean("localEcho", echo);
        }
        else
        {
            j.WriteNull("localEcho");
        }

        j.WriteStartArray("units");
        foreach ((int unit, PlcModel? model, string? error) in found)
        {
            j.WriteStartObject();
            j.WriteNumber("unit", unit);
            if (model is null)
            {
                j.WriteNull("modelCode");
                j.WriteNull("model");
                j.WriteString("error", error);
            }
            else
            {
                j.WriteString("modelCode", model.Code.ToString("X2", CultureInfo.InvariantCulture));
                j.WriteString("model", model.Name);
            }

            j.WriteEndObject();
        }

        j.WriteEndArray();
        j.WriteStartArray("tries");
        foreach (ProbeTry t in outcome.Tries)
        {
            j.WriteStartObject();
            j.WriteNumber("baudRate", t.Baud);
            j.WriteString("format", t.Format.ToString());
            j.WriteNumber("unit", t.Unit);
            j.WriteString("sent", Protocol.FrameText.Printable(t.Sent));
            j.WriteString("received", Protocol.FrameText.Printable(t.Reply.Bytes));
            j.WriteNumber("copies", t.Reply.Copies);
            j.WriteNumber("badFcs", t.Reply.BadFcs);
            j.WriteNumber("unframedBytes", t.Reply.Unframed);
            j.WriteString("result", Words(t));
            j.WriteNumber("milliseconds", Math.Round(t.Elapsed.TotalMilliseconds, 3));
            j.WriteEndObject();
        }

        j.WriteEndArray();
        j.WriteStartArray("diagnosis");
        foreach (string sentence in diagnosis)
        {
            j.WriteStringValue(sentence);
        }

        j.WriteEndArray();
        if (settings is not null && found.Count > 0)
        {
            bool echoOn = outcome.Echo == true;
            j.WriteString("flags", Flags(settings, tcp, echoOn, found[0].Unit));
            j.WritePropertyName("configuration");
            using JsonDocument configuration = JsonDocument.Parse(Configuration(settings, tcp, echoOn, found[0].Unit));
            configuration.RootElement.WriteTo(j);
        }

        j.WriteNumber("elapsedMs", Math.Round(outcome.Elapsed.TotalMilliseconds, 1));
        j.WriteEndObject();
    }

    private static IReadOnlyList<int> ParseSpeeds(string? text)
    {
        if (text is null)
        {
            return Speeds;
        }

        var list = new List<int>();
        foreach (string part in text.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            if (!int.TryParse(part, NumberStyles.None, CultureInfo.InvariantCulture, out int speed) || SettingRules.BaudRate(speed) is not null)
            {
                throw new UsageException($"--speeds: '{part}' is not a standard rate ({string.Join(", ", SettingRules.StandardBaudRates)}).");
            }

            list.Add(speed);
        }

        return list.Count > 0 ? list : throw new UsageException("--speeds: give at least one speed, e.g. 9600,19200.");
    }

    private static IReadOnlyList<LineFormat> ParseFormats(string? text)
    {
        if (text is null)
        {
            return LineFormat.Usual;
        }

        var list = new List<LineFormat>();
        foreach (string part in text.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            if (!LineFormat.TryParse(part, out LineFormat format))
            {
                throw new UsageException($"--formats: '{part}' is not a format such as 7E2 or 8N1 (data bits 7 or 8, parity E, O or N, stop bits 1 or 2).");
            }

            list.Add(format);
        }

        return list.Count > 0 ? list : throw new UsageException("--formats: give at least one format, e.g. 7E2,8N1.");
    }

    private static string UnitWords(IReadOnlyList<int> units)
    {
        if (units.Count == 1)
        {
            return $"unit {units[0]:D2}";
        }

        bool run = units.Zip(units.Skip(1)).All(p => p.Second == p.First + 1);
        return run ? $"units {units[0]:D2}-{units[^1]:D2}" : $"units {string.Join(",", units.Select(u => u.ToString("D2", CultureInfo.InvariantCulture)))}";
    }

    private static string Milliseconds(TimeSpan t) => t.TotalMilliseconds.ToString("0.0", CultureInfo.InvariantCulture) + " ms";
}
