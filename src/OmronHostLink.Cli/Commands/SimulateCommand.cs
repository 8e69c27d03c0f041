using System.CommandLine;
using System.Globalization;
using System.Net;
using System.Net.Sockets;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Simulator.Replay;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>simulate</c>: runs a virtual CS/CJ PLC on TCP or a serial port until Ctrl+C.</summary>
internal static class SimulateCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("simulate", "Run a virtual CS/CJ PLC (C-mode) on TCP (default 127.0.0.1:9600) or a serial port. Ctrl+C stops cleanly.");
        var tcp = new Option<string?>("--tcp") { Description = "Listen on host:port (default 127.0.0.1:9600; port 0 picks a free one).", HelpName = "host:port" };
        var port = new Option<string?>("--port") { Description = "Serve a serial port or pty path instead (e.g. one end of a socat pair).", HelpName = "name" };
        var units = new Option<string>("--units") { Description = "Unit numbers on the line: 0,1 or 0-3. Each is a PLC of its own (memory, mode, errors) unless --shared-memory.", DefaultValueFactory = _ => "0", HelpName = "list" };
        var shared = new Option<bool>("--shared-memory") { Description = "Make the --units one PLC answering to all of them (one memory, mode and error state)." };
        var readyFile = new Option<string?>("--ready-file") { Description = "Write the address served (host:port, or the serial port) to this file once the simulator accepts connections; the file is removed when it stops.", HelpName = "path" };
        Option<string> mode = OptionValues.Choice("--mode", "Operating mode at start.", "program", "program", "monitor", "run");
        var memory = new Option<string?>("--memory") { Description = "JSON file with initial memory and state, e.g. {\"D100\":[1,2,3],\"mode\":\"run\"}.", HelpName = "file.json" };
        Option<int?> baud = OptionValues.OptionalInteger("--baud", "Line speed: on TCP, emulate the wire time of this speed (default none); on a serial port, the port's speed (default 9600).", 1, 10_000_000, "n");
        Option<int> dataBits = OptionValues.Integer("--data-bits", $"Serial data bits: {SettingRules.MinDataBits} or {SettingRules.MaxDataBits}.", new SerialLineSettings().DataBits, int.MinValue, int.MaxValue, $"{SettingRules.MinDataBits}|{SettingRules.MaxDataBits}");
        Option<string> parity = OptionValues.Choice("--parity", "Serial parity.", "even", "none", "even", "odd");
        Option<int> stopBits = OptionValues.Integer("--stop-bits", "Serial stop bits: 1 or 2.", (int)new SerialLineSettings().StopBits, int.MinValue, int.MaxValue, "1|2");
        Option<TimeSpan?> turnaround = Durations.Option("--turnaround", "Time between a command and its answer.", TimeSpan.Zero, TimeSpan.Zero, TimeSpan.FromMinutes(1));
        var model = new Option<string?>("--model") { Description = "The PLC model to emulate (CPM1A, C200HS, CP1E-E, ...: its areas, commands and MM code; see 'hostlink model --list'), or just the code MM reports, two hex digits (default 30 = CS/CJ).", HelpName = "name|hex" };
        Option<string?> compatibleMode = OptionValues.OptionalChoice("--compatible-mode", "Answer as a Serial Communications Unit in this Host Link-compatible device mode (A: CS/CJ/C, B: CVM1/CV, C: C200H): its words per answer frame and its MS answer (default: a CPU Unit's own port).", "a|b|c", "a", "b", "c");
        var drop = OptionValues.Probability("--fault-drop", "Probability of not answering at all.");
        var corrupt = OptionValues.Probability("--fault-corrupt", "Probability of corrupting a character (the FCS no longer matches).");
        var noise = OptionValues.Probability("--fault-noise", "Probability of sending noise bytes before a frame.");
        var truncate = OptionValues.Probability("--fault-truncate", "Probability of cutting a frame short.");
        var late = OptionValues.Probability("--fault-late", "Probability of answering late (after the host's deadline).");
        var outOfTurn = OptionValues.Probability("--fault-out-of-turn", "Probability of holding an answer back and sending it between the answers to later commands.");
        var echo = OptionValues.Probability("--fault-echo", "Probability of echoing the command first, as a 2-wire RS-485 line does.");
        Option<TimeSpan?> lateBy = Durations.Option("--fault-late-by", "How late a late answer comes.", TimeSpan.FromSeconds(1), TimeSpan.Zero, TimeSpan.FromMinutes(10));
        Option<int> seed = OptionValues.Integer("--fault-seed", "Seed of the fault generator (same seed, same faults).", 1, int.MinValue, int.MaxValue, "n");
        var capture = new Option<string?>("--capture") { Description = "Write every frame received and sent, with its time and direction, to this file: a pcap for Wireshark (tools/wireshark/omron-hostlink.lua), or JSON lines for a name ending in .jsonl.", HelpName = "file" };
        var replay = new Option<string?>("--replay") { Description = "Answer as the PLC in this capture did (a pcap from monitor-line --capture, a client's trace or simulate --capture): each command gets the answer recorded for it, in turn; TS is echoed; a command not in the capture gets no answer. Replaces the virtual PLC: --units, --shared-memory, --memory, --model, --mode, --compatible-mode, --turnaround and the faults do not apply.", HelpName = "capture.pcap" };
        Option[] plcOptions = [units, shared, mode, memory, model, compatibleMode, drop, corrupt, noise, truncate, late, outOfTurn, lateBy, echo, seed, turnaround];
        foreach (Option o in new Option[] { tcp, port, units, shared, readyFile, mode, memory, baud, dataBits, parity, stopBits, turnaround, model, compatibleMode, drop, corrupt, noise, truncate, late, outOfTurn, lateBy, echo, seed, capture, replay })
        {
            command.Add(o);
        }

        context.SetAction(command, null, async (parse, output, ct) =>
        {
            string? tcpText = parse.GetValue(tcp);
            string? portName = parse.GetValue(port);
            if (tcpText is not null && portName is not null)
            {
                throw new UsageException("Give either --tcp or --port, not both.");
            }

            int? baudRate = parse.GetValue(baud);
            if (parse.GetValue(replay) is { } replayFile)
            {
                if (plcOptions.FirstOrDefault(o => parse.GetResult(o) is { Implicit: false }) is { } given)
                {
                    throw new UsageException($"--replay answers as the capture does: {given.Name} cannot be combined with it.");
                }

                if (parse.GetValue(capture) is not null)
                {
                    throw new UsageException("--replay answers from a capture: --capture cannot be combined with it.");
                }

                return await ReplayAsync(parse, output, replayFile, tcpText, portName, baudRate, Serial(parse, portName, baudRate, dataBits, parity, stopBits), parse.GetValue(readyFile), ct).ConfigureAwait(false);
            }

            var options = new VirtualPlcOptions
            {
                Units = Numbers.ParseUnits(parse.GetValue(units)!, "--units"),
                InitialMode = parse.GetValue(mode) switch
                {
                    "run" => PlcMode.Run,
                    "monitor" => PlcMode.Monitor,
                    _ => PlcMode.Program,
                },
                BaudRate = baudRate ?? 0,
                Turnaround = parse.GetValue(turnaround) ?? TimeSpan.Zero,
                Faults = new FaultOptions
                {
                    Seed = parse.GetValue(seed),
                    Drop = parse.GetValue(drop),
                    Corrupt = parse.GetValue(corrupt),
                    Noise = parse.GetValue(noise),
                    Truncate = parse.GetValue(truncate),
                    Late = parse.GetValue(late),
                    OutOfTurn = parse.GetValue(outOfTurn),
                    LateBy = parse.GetValue(lateBy) ?? TimeSpan.FromSeconds(1),
                    Echo = parse.GetValue(echo),
                },
            };
            options.HostLinkCompatibleMode = parse.GetValue(compatibleMode) switch
            {
                "a" => HostLinkCompatibleMode.ModeA,
                "b" => HostLinkCompatibleMode.ModeB,
                "c" => HostLinkCompatibleMode.ModeC,
                _ => null,
            };
            if (parse.GetValue(model) is { } modelText)
            {
                if (modelText.Length <= 2 && byte.TryParse(modelText, NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out byte code))
                {
                    options.ModelCode = code;
                }
                else if (PlcModelProfile.TryParse(modelText, out PlcModelProfile? profile))
                {
                    options.Model = profile.Name;
                }
                else
                {
                    throw new UsageException($"--model '{modelText}' is neither a known PLC model ({PlcModelProfile.KnownNames()}) nor two hex digits such as 30.");
                }
            }

            SerialLineSettings? serial = Serial(parse, portName, baudRate, dataBits, parity, stopBits);
            if (serial is not null)
            {
                options.BitsPerCharacter = serial.BitsPerCharacter;
            }

            SimulatorFrameLog? log = null;
            if (parse.GetValue(capture) is { } captureFile)
            {
                try
                {
                    log = new SimulatorFrameLog(captureFile);
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    throw new UsageException($"--capture: cannot create '{captureFile}': {e.Message}", e);
                }

                options.FrameLog = log;
            }

            bool oneCpu = parse.GetValue(shared) || options.Units.Count == 1;
            VirtualPlcLine line;
            try
            {
                options.Validate();
                line = oneCpu ? new VirtualPlcLine([new VirtualPlc(options)]) : VirtualPlcLine.OnePlcPerUnit(options);
                if (parse.GetValue(memory) is { } file)
                {
                    foreach (VirtualPlc plc in line.Plcs)
                    {
                        plc.LoadJsonFile(file);
                    }
                }
            }
            catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException)
            {
                throw new UsageException($"The initial memory cannot be loaded: {e.Message}", e);
            }

            string? ready = parse.GetValue(readyFile);
            if (ready is not null)
            {
                // A file left by an earlier run must not announce this one before it listens.
                ReadyFile.Remove(ready);
            }

            string unitList = string.Join(",", options.Units.Select(u => u.ToString("D2", CultureInfo.InvariantCulture)));
            VirtualPlc first = line.Plcs[0];
            string memoryText = parse.GetValue(memory) is { } memoryFile ? $"memory from {Path.GetFileName(memoryFile)}" : "memory all zero";
            string state = $"{StatusCommand.ModeName(first.Mode)} mode, {memoryText}, "
                + (first.Model is { } emulated ? $"emulating {emulated.WithArticle()} (MM {(emulated.ModelCode is { } mm ? mm.ToString("X2", CultureInfo.InvariantCulture) : "answered IC")})" : $"model code {first.ModelCode:X2}")
                + (options.HostLinkCompatibleMode is { } compatible ? $", framed as a Serial Communications Unit in Host Link-compatible {CompatibleModeFraming.Of(compatible).Name}" : string.Empty)
                + (options.Units.Count == 1 ? string.Empty : oneCpu ? ", one PLC answering every unit" : ", each unit a PLC of its own");
            try
            {
                if (serial is not null)
                {
                    // The host reopens the port when it is lost (socat restarted, an adapter unplugged) until Ctrl+C.
                    await using var host = new SerialSimulatorHost(line, serial, output.Note);
                    await host.StartAsync(ct).ConfigureAwait(false);
                    output.Line($"Simulating units {unitList} ({state}) on {serial}. Ctrl+C stops.");
                    RunModeNote(output, line, $"--port {serial.PortName}");
                    ReadyFile.Write(ready, serial.PortName);
                    await Task.WhenAny(host.Completion, Task.Delay(Timeout.Infinite, ct)).ConfigureAwait(false);
                    await host.StopAsync(CancellationToken.None).ConfigureAwait(false);
                }
                else
                {
                    await ServeTcpAsync(line, tcpText, unitList, state, ready, output, ct).ConfigureAwait(false);
                }
            }
            finally
            {
                if (ready is not null)
                {
                    ReadyFile.Remove(ready);
                }

                log?.Dispose();
            }

            output.Line(log is null ? "Simulator stopped." : $"Simulator stopped; {log.Count} frames captured.");
            return ExitCodes.Success;
        });
        return command;
    }

    /// <summary>Says, when a PLC starts in RUN mode, that C-mode writes are refused and how to get past it.</summary>
    private static void RunModeNote(OutputWriter output, VirtualPlcLine line, string where)
    {
        if (line.Plcs.Any(p => p.Mode == PlcMode.Run))
        {
            output.Line($"In RUN mode a CS/CJ refuses C-mode writes (end code 01): switch with 'hostlink mode monitor --yes {where}', or write with --fins.");
        }
    }

    /// <summary>The serial port's settings from the options, or null when serving TCP.</summary>
    private static SerialLineSettings? Serial(ParseResult parse, string? portName, int? baudRate, Option<int> dataBits, Option<string> parity, Option<int> stopBits)
    {
        if (portName is null)
        {
            return null;
        }

        var serial = new SerialLineSettings
        {
            PortName = portName,
            BaudRate = baudRate ?? HostLinkSerialSettings.BaudRateSetting.Default!.Value,
            DataBits = parse.GetValue(dataBits),
            Parity = parse.GetValue(parity) switch { "none" => SerialParity.None, "odd" => SerialParity.Odd, _ => SerialParity.Even },
            StopBits = (SerialStopBits)parse.GetValue(stopBits),
        };
        try
        {
            serial.Validate();
        }
        catch (ArgumentException e)
        {
            throw new UsageException(OptionValues.SerialMessage(e), e);
        }

        return serial;
    }

    /// <summary><c>--replay</c>: serves a PLC that answers as a capture recorded, until Ctrl+C.</summary>
    private static async Task<int> ReplayAsync(ParseResult parse, OutputWriter output, string file, string? tcpText, string? portName, int? baudRate, SerialLineSettings? serial, string? ready, CancellationToken ct)
    {
        CaptureReplay replay;
        try
        {
            replay = CaptureReplay.Load(file, baudRate ?? 0, serial?.BitsPerCharacter ?? 11, output.Note);
        }
        catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"--replay: {e.Message}", e);
        }

        string units = string.Join(",", replay.Units.Select(u => u.ToString("D2", CultureInfo.InvariantCulture)));
        string what = $"Replaying {replay.Exchanges} exchanges of {replay.Name} (units {units}: each command gets the answer recorded for it, TS is echoed, others get none)";
        if (ready is not null)
        {
            ReadyFile.Remove(ready);
        }

        try
        {
            if (serial is not null)
            {
                await using var host = new SerialSimulatorHost(replay, serial, output.Note);
                await host.StartAsync(ct).ConfigureAwait(false);
                output.Line($"{what} on {serial}. Ctrl+C stops.");
                ReadyFile.Write(ready, serial.PortName);
                await Task.WhenAny(host.Completion, Task.Delay(Timeout.Infinite, ct)).ConfigureAwait(false);
                await host.StopAsync(CancellationToken.None).ConfigureAwait(false);
            }
            else
            {
                (string h, int p) = tcpText is null ? ("127.0.0.1", 9600) : ParseListen(tcpText);
                IPAddress address = Address(h);
                await using var host = new TcpSimulatorHost(replay, new IPEndPoint(address, p));
                await ListenAsync(host, h, p).ConfigureAwait(false);
                output.Line($"{what} on {host.EndPoint}. Ctrl+C stops.");
                ReadyFile.Write(ready, host.EndPoint.ToString());
                await WaitForStopAsync(ct).ConfigureAwait(false);
                await host.StopAsync(CancellationToken.None).ConfigureAwait(false);
            }
        }
        finally
        {
            if (ready is not null)
            {
                ReadyFile.Remove(ready);
            }
        }

        output.Line(replay.Unmatched == 0 ? "Replay stopped." : $"Replay stopped; {replay.Unmatched} command{(replay.Unmatched == 1 ? " was" : "s were")} not in the capture.");
        return ExitCodes.Success;
    }

    private static async Task ServeTcpAsync(VirtualPlcLine line, string? tcpText, string unitList, string state, string? ready, OutputWriter output, CancellationToken ct)
    {
        (string h, int p) = tcpText is null ? ("127.0.0.1", 9600) : ParseListen(tcpText);
        IPAddress address = Address(h);
        await using var host = new TcpSimulatorHost(line, new IPEndPoint(address, p));
        await ListenAsync(host, h, p).ConfigureAwait(false);

        // Listening now: a client that connects from here on is served.
        output.Line($"Simulating units {unitList} ({state}) on {host.EndPoint}. Ctrl+C stops.");
        RunModeNote(output, line, $"--tcp {host.EndPoint}");
        ReadyFile.Write(ready, host.EndPoint.ToString());
        await WaitForStopAsync(ct).ConfigureAwait(false);
        await host.StopAsync(CancellationToken.None).ConfigureAwait(false);
    }

    private static IPAddress Address(string h)
        => h is "localhost" ? IPAddress.Loopback : IPAddress.TryParse(h, out IPAddress? ip) ? ip
            : throw new UsageException($"--tcp: '{h}' is not an IP address to listen on (use 127.0.0.1, 0.0.0.0 or ::).");

    private static async Task ListenAsync(TcpSimulatorHost host, string h, int p)
    {
        try
        {
            await host.StartAsync().ConfigureAwait(false);
        }
        catch (SocketException e)
        {
            throw new HostLinkConnectionException($"Cannot listen on {h}:{p}: {e.Message}", e);
        }
    }

    private static async Task WaitForStopAsync(CancellationToken ct)
    {
        try
        {
            await Task.Delay(Timeout.Infinite, ct).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
        }
    }

    private static (string Host, int Port) ParseListen(string text)
    {
        int colon = text.LastIndexOf(':');
        if (colon <= 0 || !int.TryParse(text.AsSpan(colon + 1), NumberStyles.None, CultureInfo.InvariantCulture, out int p) || p > SettingRules.MaxTcpPort)
        {
            throw new UsageException($"--tcp '{text}' is not host:port with a port 0-{SettingRules.MaxTcpPort}.");
        }

        return (text[..colon].Trim('[', ']'), p);
    }
}
