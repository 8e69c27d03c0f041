using System.Buffers.Binary;
using System.Globalization;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;
using OmronHostLink.Capture;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Simulator.Replay;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// Captures: tshark with the repository's dissector decodes what the simulator and the monitor write (every frame's unit,
/// command, end code and FCS verdict checked against the frame's own characters), a serial-device server's TCP stream,
/// <c>explain</c> reads a capture, and a captured session replayed gives the client the same values.
/// </summary>
public sealed class CliCaptureTests : IDisposable
{
    private static readonly string[] Fields = ["hostlink.direction", "hostlink.kind", "hostlink.unit", "hostlink.header", "hostlink.end_code", "hostlink.fcs.status"];

    private readonly string _dir = Directory.CreateTempSubdirectory("ohl-capture-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public async Task Tshark_decodes_every_frame_of_a_capture_the_simulator_wrote_and_flags_bad_fcs()
    {
        string capture = Path.Combine(_dir, "simulator.pcap");
        var log = new SimulatorFrameLog(capture, keepFrames: true);
        var plc = new VirtualPlc(new VirtualPlcOptions { FrameLog = log, Faults = new FaultOptions { Corrupt = 0.2, Seed = 11 } });
        (Stream hostEnd, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = plc.RunAsync(plcEnd, stop.Token);
        await using (HostLinkClient client = HostLinkClient.ForStream(hostEnd, new HostLinkClientOptions { TurnaroundAllowance = TimeSpan.FromSeconds(2), ReadRetries = 5 }))
        {
            for (int i = 0; i < 4; i++)
            {
                await SessionAsync(client, plc, tolerateFaults: true);
            }
        }

        await stop.CancelAsync();
        await session;
        log.Dispose();

        IReadOnlyList<CapturedFrame> records = CaptureReader.Read(capture);
        records.Select(r => r.Bytes).Should().Equal(log.Frames.Select(f => f.Bytes.ToArray()), (a, b) => a.AsSpan().SequenceEqual(b));
        records.Where(r => !FrameCheck.Of(r.Bytes).FcsMatches && r.Bytes.Length > 1).Should().NotBeEmpty("the corrupt fault damaged some answers");
        await CheckDissectionAsync(capture, records);
    }

    [Fact]
    [Trait("Category", "Slow")]
    public async Task Tshark_decodes_every_frame_of_a_capture_the_monitor_wrote_and_flags_bad_fcs()
    {
        await using TappedSerialLine line = await TappedSerialLine.StartAsync(115200, 10);
        var log = new SimulatorFrameLog();
        var plc = new VirtualPlc(new VirtualPlcOptions { FrameLog = log, Faults = new FaultOptions { Corrupt = 0.2, Seed = 5 } });
        await using var host = new SerialSimulatorHost(plc, () => line.PlcStream);
        await host.StartAsync();
        string capture = Path.Combine(_dir, "monitor.pcap");
        await using HostlinkProcess monitor = HostlinkProcess.Start("monitor-line", "--port", line.TapPort!, "--baud", "115200", "--data-bits", "8", "--parity", "none", "--stop-bits", "1", "--capture", capture, "--summary-every", "0");
        await monitor.ExpectOutputAsync("Listening", TimeSpan.FromSeconds(30), onStandardError: true);
        var settings = new SerialLineSettings { PortName = line.HostPort, BaudRate = 115200, DataBits = 8, Parity = SerialParity.None, StopBits = SerialStopBits.One };
        await using (HostLinkClient client = HostLinkClient.ForSerialPort(settings, new HostLinkClientOptions { TurnaroundAllowance = Allowances.LosslessLine, ReadRetries = 5 }))
        {
            for (int i = 0; i < 3; i++)
            {
                await SessionAsync(client, plc, tolerateFaults: true);
            }
        }

        long logged = log.Count;
        // The monitor writes its capture within a second of each frame.
        await Eventually.UntilAsync(() => CaptureRecords(capture) >= logged, "the monitor's capture holds every frame the simulator logged", () => $"It holds {CaptureRecords(capture)} of {logged}.");

        (await monitor.StopAsync(TimeSpan.FromSeconds(10))).Should().BeTrue("the monitor stops on SIGTERM: {0}", monitor);
        await host.StopAsync();

        IReadOnlyList<CapturedFrame> records = CaptureReader.Read(capture);
        var heardFrames = records.Select(r => (FrameText.Printable(r.Bytes), r.Direction)).ToList();
        var loggedFrames = log.Frames.Select(f => (f.Text, f.FromHost ? LineDirection.ToPlc : LineDirection.FromPlc)).ToList();
        int differ = Enumerable.Range(0, Math.Min(heardFrames.Count, loggedFrames.Count)).FirstOrDefault(i => heardFrames[i] != loggedFrames[i], -1);
        heardFrames.Should().Equal(
            loggedFrames,
            "the monitor captured every frame the simulator logged, each with its direction (first difference at {0}: heard {1}, logged {2})",
            differ,
            differ < 0 ? "" : string.Join(" ", heardFrames.Skip(Math.Max(0, differ - 2)).Take(5)),
            differ < 0 ? "" : string.Join(" ", loggedFrames.Skip(Math.Max(0, differ - 2)).Take(5)));
        records.Where(r => !FrameCheck.Of(r.Bytes).FcsMatches && r.Bytes.Length > 1).Should().NotBeEmpty("the corrupt fault damaged some answers");
        await CheckDissectionAsync(capture, records);
    }

    [Fact]
    public async Task Tshark_decodes_host_link_in_the_tcp_stream_of_a_serial_device_server()
    {
        // Golden frames: an RD (dws_rd_dm_read) and its answer (c_rd_resp_3w), the answer split across two segments;
        // then the RD with its FCS changed, and the PLC's end code 13 (c_rd_err_13).
        string capture = Path.Combine(_dir, "server.pcap");
        string rd = GoldenFrames.Frames("dws_rd_dm_read")[0];
        string answer = GoldenFrames.Frames("c_rd_resp_3w")[0];
        string damaged = rd.Replace("57*", "58*", StringComparison.Ordinal);
        WriteTcpCapture(capture, [(false, rd), (true, answer[..12]), (true, answer[12..]), (false, damaged), (true, GoldenFrames.Frames("c_rd_err_13")[0])]);

        List<string[]> rows = (await Tshark.FieldsAsync(capture, Fields)).Where(r => r[3].Length > 0).ToList();

        rows.Select(r => (r[0], r[2], r[3], r[4], r[5])).Should().Equal(
            ("1", "0", "RD", "", "good"),
            ("2", "0", "RD", "00", "good"),
            ("1", "0", "RD", "", "bad"),
            ("2", "0", "RD", "13", "good"));
    }

    [Fact]
    public void The_dissector_names_commands_end_codes_and_fins_commands_as_the_library_does()
    {
        string lua = File.ReadAllText(Tshark.Dissector);
        Dictionary<string, string> commands = LuaTable(lua, "commands");
        Dictionary<string, string> endCodes = LuaTable(lua, "end_codes");
        Dictionary<string, string> fins = LuaTable(lua, "fins_commands");

        foreach (CModeCommandRow row in CModeCommandTable.Standard.Rows)
        {
            commands.Should().ContainKey(row.Key).WhoseValue.Should().Be(row.Name, "the dissector names {0} as the library does", row.Key);
        }

        commands.Keys.Should().BeEquivalentTo(CModeCommandTable.Standard.Rows.Select(r => r.Key));
        foreach (EndCode code in EndCodes.All.Where(c => c != EndCode.UndefinedHeader))
        {
            endCodes.Should().ContainKey(code.ToCode()).WhoseValue.Should().Be(code.Meaning());
        }

        fins.Should().BeEquivalentTo(FinsCommandTable.Standard.Rows.ToDictionary(r => r.Code.ToString("X4", CultureInfo.InvariantCulture), r => r.Name));
    }

    [Fact]
    public async Task Explain_reads_a_capture_frame_by_frame()
    {
        string capture = Path.Combine(_dir, "explain.pcap");
        var t0 = DateTimeOffset.UtcNow;
        using (CaptureWriter writer = CaptureWriter.Create(capture))
        {
            writer.Write(t0, LineDirection.ToPlc, Encoding.ASCII.GetBytes(GoldenFrames.Frames("c_mm")[0]));
            writer.Write(t0.AddMilliseconds(2), LineDirection.FromPlc, Encoding.ASCII.GetBytes(GoldenFrames.Frames("c_mm_resp_csj")[0]));
            writer.Write(t0.AddMilliseconds(9), LineDirection.FromPlc, Encoding.ASCII.GetBytes("@00MM003044*\r"));
        }

        CliResult human = await Cli.RunAsync("explain", capture);
        CliResult json = await Cli.RunAsync("explain", capture, "--json");

        human.ExitCode.Should().Be(0, human.ToString());
        human.Out.Should().Contain("#1").And.Contain("host to PLC").And.Contain("PLC MODEL READ");
        human.Out.Should().Contain("#2").And.Contain("PLC to host").And.Contain("End code:   00");
        human.Out.Should().Contain("FCS:        found 44, expected 43: MISMATCH");
        human.Err.Should().Contain("3 records, 1 not valid");
        string[] lines = json.Lines();
        lines.Should().HaveCount(3);
        JsonElement second = JsonDocument.Parse(lines[1]).RootElement;
        second.GetProperty("direction").GetString().Should().Be("fromPlc");
        second.GetProperty("explanation").GetProperty("fields").GetProperty("modelCode").GetString().Should().Be("30");
    }

    [Fact]
    public async Task A_captured_session_replayed_gives_the_client_the_same_values()
    {
        string trace = Path.Combine(_dir, "session.pcap");
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0] });
        for (int i = 0; i < 60; i++)
        {
            plc.WriteWord(PlcArea.Dm, i, (ushort)((i * 977) & 0xFFFF));
        }

        plc.FalMessage = "LINE 4 STOPPED";
        List<string> original;
        await using (var tcp = new TcpSimulatorHost(plc))
        {
            await tcp.StartAsync();
            await using HostLinkClient client = HostLinkClient.ForTcp("127.0.0.1", tcp.EndPoint.Port, new HostLinkClientOptions { TurnaroundAllowance = Allowances.LosslessLine, TraceFile = trace });
            original = await SessionAsync(client, plc, tolerateFaults: false);
        }

        // The simulator the values came from is gone; the replay has only the client's trace.
        CaptureReplay replay = CaptureReplay.Load(trace);
        await using var host = new TcpSimulatorHost(replay);
        await host.StartAsync();
        List<string> replayed;
        await using (HostLinkClient client = HostLinkClient.ForTcp("127.0.0.1", host.EndPoint.Port, new HostLinkClientOptions { TurnaroundAllowance = Allowances.LosslessLine }))
        {
            replayed = await SessionAsync(client, plc: null, tolerateFaults: false);
        }

        replayed.Should().Equal(original);
        original.Should().Contain("D0-D39: " + string.Join(",", Enumerable.Range(0, 40).Select(i => (i * 977) & 0xFFFF)));
        replay.Unmatched.Should().Be(0);
    }

    [Fact]
    public async Task Simulate_writes_a_capture_and_replays_one()
    {
        string capture = Path.Combine(_dir, "console.pcap");
        string ready = Path.Combine(_dir, "sim.ready");
        using (var stop = new CancellationTokenSource())
        {
            Task<CliResult> sim = Cli.RunAsync(stop.Token, "simulate", "--tcp", "127.0.0.1:0", "--ready-file", ready, "--capture", capture, "--memory", WriteMemory("{\"D10\":[4660,22136]}"));
            string endpoint = await ReadyAsync(ready, sim);
            (await Cli.RunAsync("read", "D10", "2", "--tcp", endpoint)).Out.Should().Contain("0x1234").And.Contain("0x5678");
            await stop.CancelAsync();
            CliResult stopped = await sim;
            stopped.Out.Should().Contain("memory from").And.Contain("2 frames captured");
        }

        using (var stop = new CancellationTokenSource())
        {
            Task<CliResult> sim = Cli.RunAsync(stop.Token, "simulate", "--tcp", "127.0.0.1:0", "--ready-file", ready, "--replay", capture);
            string endpoint = await ReadyAsync(ready, sim);
            CliResult read = await Cli.RunAsync("read", "D10", "2", "--tcp", endpoint, "--json");
            CliResult other = await Cli.RunAsync("read", "D11", "--tcp", endpoint, "--timeout", "200ms", "--retries", "0");
            await stop.CancelAsync();
            CliResult stopped = await sim;

            read.Json().GetProperty("values").EnumerateArray().Select(v => v.GetInt32()).Should().Equal(0x1234, 0x5678);
            other.ExitCode.Should().Be(4, "a command the capture does not hold gets no answer: {0}", other);
            stopped.Out.Should().Contain("Replaying 1 exchanges of console.pcap (units 00");
            stopped.Err.Should().Contain("Not in console.pcap, so not answered: @00RD0011000157*\\r");
        }
    }

    [Fact]
    public async Task Replay_refuses_the_options_of_a_virtual_plc()
    {
        CliResult r = await Cli.RunAsync("simulate", "--replay", Path.Combine(_dir, "x.pcap"), "--units", "0,1");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--replay answers as the capture does: --units cannot be combined with it.");
    }

    /// <summary>
    /// The same exchanges each time: reads (one frame and a divided answer), a divided write, status, model, TS, a FINS read,
    /// a write refused in RUN mode (end code 01) and an unknown header (IC). The values read, as text.
    /// </summary>
    private static async Task<List<string>> SessionAsync(HostLinkClient client, VirtualPlc? plc, bool tolerateFaults)
    {
        var values = new List<string>();
        async Task Step(string name, Func<Task<string>> call)
        {
            try
            {
                values.Add($"{name}: {await call()}");
            }
            catch (Exception e) when (e is HostLinkException && (tolerateFaults || e is HostLinkEndCodeException))
            {
                values.Add($"{name}: {e.GetType().Name} {(e as HostLinkEndCodeException)?.EndCode.ToCode()}");
            }
        }

        await Step("D0-D2", async () => string.Join(",", await client.ReadWordsAsync("D0", 3)));
        await Step("D0-D39", async () => string.Join(",", await client.ReadWordsAsync("D0", 40)));
        await Step("WD", async () =>
        {
            await client.WriteWordsAsync("D500", Enumerable.Range(0, 40).Select(i => (ushort)i).ToArray());
            return "ok";
        });
        await Step("MS", async () => (await client.ReadStatusAsync()).ToString() ?? "");
        await Step("MM", async () => (await client.ReadModelAsync()).ToString() ?? "");
        await Step("TS", async () => (await client.TestAsync("REPLAY")).Ticks >= 0 ? "echoed" : "?");
        await Step("FINS", async () => string.Join(",", await client.Unit(0, HostLinkCommandSet.Fins).ReadWordsAsync("D1", 2)));
        if (plc is not null)
        {
            plc.Mode = PlcMode.Run;
        }

        await Step("WD in RUN", async () =>
        {
            await client.WriteWordAsync("D600", 1);
            return "ok";
        });
        if (plc is not null)
        {
            plc.Mode = PlcMode.Program;
        }

        await Step("IC", async () => Encoding.ASCII.GetString(await client.ExchangeRawAsync("XX", expectsResponse: true)));
        return values;
    }

    /// <summary>
    /// Runs tshark with the dissector over the capture and checks every frame's unit, header, end code and FCS verdict
    /// against what the frame's own characters say (sliced here; the FCS checked by the library, not the dissector).
    /// </summary>
    private static async Task CheckDissectionAsync(string capture, IReadOnlyList<CapturedFrame> records)
    {
        List<string[]> rows = await Tshark.FieldsAsync(capture, Fields);
        rows.Should().HaveCount(records.Count, "tshark shows every record");
        var lastFirst = new Dictionary<LineDirection, (string Unit, string Header)>();
        for (int i = 0; i < records.Count; i++)
        {
            CapturedFrame r = records[i];
            string[] row = rows[i];
            string direction = ((int)r.Direction).ToString(CultureInfo.InvariantCulture);
            string text = Encoding.Latin1.GetString(r.Bytes);
            (string Kind, string Unit, string Header, string EndCode, string Fcs) expected;
            if ((r.Flags & CaptureFlags.NotFramed) != 0)
            {
                expected = ("noise", "", "", "", "");
            }
            else if (text == "\r")
            {
                expected = ("delimiter", "", "", "", "");
            }
            else if (text.StartsWith("@**", StringComparison.Ordinal))
            {
                expected = ("initialize", "", "**", "", "");
            }
            else
            {
                FrameCheck check = FrameCheck.Of(r.Bytes);
                string fcs = check.FcsMatches ? "good" : "bad";
                if (text[0] == '@')
                {
                    string unit = int.Parse(text.AsSpan(1, 2), CultureInfo.InvariantCulture).ToString(CultureInfo.InvariantCulture);
                    string header = text.Substring(3, 2);
                    string body = text[5..check.FcsAt];
                    int sub = header == "QQ" ? 2 : 0;
                    string endCode = r.Direction != LineDirection.FromPlc || header is "IC" or "EX" ? ""
                        : header == "TS" ? (body.Length == 2 ? body : "")
                        : body.Substring(sub, 2);
                    lastFirst[r.Direction] = (unit, header);
                    expected = (r.Direction == LineDirection.FromPlc ? "answer" : "command", unit, header, endCode, fcs);
                }
                else
                {
                    (string unit, string header) = lastFirst[r.Direction];
                    expected = ("continuation", unit, header, "", fcs);
                }
            }

            (row[0], row[1], row[2], row[3], row[4], row[5]).Should().Be(
                (direction, expected.Kind, expected.Unit, expected.Header, expected.EndCode, expected.Fcs),
                "record {0} ({1}) is dissected as its characters say",
                i + 1,
                FrameText.Printable(r.Bytes));
        }

        rows.Should().Contain(row => row[5] == "bad", "a frame with a bad FCS is flagged");
    }

    private static int CaptureRecords(string capture)
    {
        try
        {
            return CaptureReader.Read(File.ReadAllBytes(capture), "monitor.pcap").Count;
        }
        catch (Exception e) when (e is IOException or FormatException)
        {
            return 0;
        }
    }

    private string WriteMemory(string json)
    {
        string path = Path.Combine(_dir, "memory.json");
        File.WriteAllText(path, json);
        return path;
    }

    private static async Task<string> ReadyAsync(string ready, Task<CliResult> sim)
    {
        await Eventually.UntilAsync(() => File.Exists(ready) || sim.IsCompleted, "simulate is ready", patience: TimeSpan.FromSeconds(20));
        if (!File.Exists(ready))
        {
            throw new Xunit.Sdk.XunitException("simulate ended before it was ready: " + await sim);
        }

        return (await File.ReadAllTextAsync(ready)).Trim();
    }

    private static Dictionary<string, string> LuaTable(string lua, string name)
    {
        int start = lua.IndexOf($"local {name} = {{", StringComparison.Ordinal);
        start.Should().BeGreaterThanOrEqualTo(0, "the dissector has a table {0}", name);
        int end = lua.IndexOf("\n}", start, StringComparison.Ordinal);
        return Regex.Matches(lua[start..end], "^\\s*(?:\\[\"(?<key>[^\"]+)\"\\]|(?<key>[A-Za-z]+)) = \"(?<value>[^\"]*)\",", RegexOptions.Multiline)
            .ToDictionary(m => m.Groups["key"].Value, m => m.Groups["value"].Value);
    }

    /// <summary>
    /// An Ethernet capture of a TCP stream between a host (127.0.0.1:50000) and a serial-device server (127.0.0.1:4001),
    /// one segment a payload, written from the pcap, IPv4 and TCP layouts (checksums left zero: tshark does not check them).
    /// </summary>
    private static void WriteTcpCapture(string path, (bool FromServer, string Payload)[] segments)
    {
        using var file = File.Create(path);
        var header = new byte[24];
        BinaryPrimitives.WriteUInt32LittleEndian(header, 0xA1B2C3D4);
        BinaryPrimitives.WriteUInt16LittleEndian(header.AsSpan(4), 2);
        BinaryPrimitives.WriteUInt16LittleEndian(header.AsSpan(6), 4);
        BinaryPrimitives.WriteUInt32LittleEndian(header.AsSpan(16), 65535);
        BinaryPrimitives.WriteUInt32LittleEndian(header.AsSpan(20), 1);
        file.Write(header);
        uint hostSeq = 1000;
        uint serverSeq = 5000;
        for (int i = 0; i < segments.Length; i++)
        {
            (bool fromServer, string payload) = segments[i];
            byte[] data = Encoding.ASCII.GetBytes(payload);
            var packet = new byte[14 + 20 + 20 + data.Length];
            BinaryPrimitives.WriteUInt16BigEndian(packet.AsSpan(12), 0x0800);
            Span<byte> ip = packet.AsSpan(14, 20);
            ip[0] = 0x45;
            BinaryPrimitives.WriteUInt16BigEndian(ip[2..], (ushort)(20 + 20 + data.Length));
            ip[8] = 64;
            ip[9] = 6;
            ip[12] = 127;
            ip[15] = 1;
            ip[16] = 127;
            ip[19] = 1;
            Span<byte> tcp = packet.AsSpan(34, 20);
            BinaryPrimitives.WriteUInt16BigEndian(tcp, fromServer ? (ushort)4001 : (ushort)50000);
            BinaryPrimitives.WriteUInt16BigEndian(tcp[2..], fromServer ? (ushort)50000 : (ushort)4001);
            BinaryPrimitives.WriteUInt32BigEndian(tcp[4..], fromServer ? serverSeq : hostSeq);
            BinaryPrimitives.WriteUInt32BigEndian(tcp[8..], fromServer ? hostSeq : serverSeq);
            tcp[12] = 0x50;
            tcp[13] = 0x18;
            BinaryPrimitives.WriteUInt16BigEndian(tcp[14..], 65535);
            data.CopyTo(packet.AsSpan(54));
            if (fromServer)
            {
                serverSeq += (uint)data.Length;
            }
            else
            {
                hostSeq += (uint)data.Length;
            }

            var record = new byte[16];
            BinaryPrimitives.WriteUInt32LittleEndian(record, 1_763_626_442);
            BinaryPrimitives.WriteUInt32LittleEndian(record.AsSpan(4), (uint)(i * 1000));
            BinaryPrimitives.WriteUInt32LittleEndian(record.AsSpan(8), (uint)packet.Length);
            BinaryPrimitives.WriteUInt32LittleEndian(record.AsSpan(12), (uint)packet.Length);
            file.Write(record);
            file.Write(packet);
        }
    }
}
