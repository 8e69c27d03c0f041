using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using System.Threading.Channels;
using OmronHostLink.Capture;
using OmronHostLink.Cli.LineMonitoring;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Commands;

/// <summary>
/// <c>monitor-line</c>: listens to a Host Link line without sending anything, on one port (a half-duplex RS-485 line,
/// both directions on one wire) or two (the receive taps of a full-duplex RS-232 line), and shows each exchange as it
/// happens: time, unit, command, end code, answer latency, FCS and framing errors, with counts per unit.
/// </summary>
internal static class MonitorLineCommand
{
    private static readonly TimeSpan TickInterval = TimeSpan.FromMilliseconds(20);

    public static Command Create(CliContext context)
    {
        var command = new Command("monitor-line", "Listen to a Host Link line without sending: on one port (a half-duplex RS-485 line) or two (--host-port and --plc-port, the receive taps of an RS-232 line). Shows each exchange (time, unit, command, end code, latency, FCS and framing errors) and counts per unit; --capture writes a pcap for Wireshark. Ctrl+C stops.");
        var line = new LineSettingsOptions("the line");
        var port = new Option<string?>("--port") { Description = "The port that hears both directions (a half-duplex RS-485 line).", HelpName = "name" };
        var hostPort = new Option<string?>("--host-port") { Description = "With --plc-port: the port that hears the host (its TX line).", HelpName = "name" };
        var plcPort = new Option<string?>("--plc-port") { Description = "With --host-port: the port that hears the PLC (its TX line).", HelpName = "name" };
        var capture = new Option<string?>("--capture") { Description = "Write every frame heard, with its time and direction, to this file: a pcap for Wireshark (tools/wireshark/omron-hostlink.lua), or JSON lines for a name ending in .jsonl.", HelpName = "file" };
        Option<TimeSpan?> duration = Durations.Option("--duration", "Stop after this long (default: until Ctrl+C).", null, TimeSpan.FromMilliseconds(1), TimeSpan.FromDays(365));
        Option<int?> count = OptionValues.OptionalInteger("--count", "Stop after this many exchanges.", 1, int.MaxValue, "n");
        Option<TimeSpan?> summaryEvery = Durations.Option("--summary-every", "Print the counts per unit this often (0: only at the end).", TimeSpan.FromSeconds(10), TimeSpan.Zero, TimeSpan.FromDays(1));
        Option<bool> json = CliContext.JsonOption("Print one JSON document per line: each exchange, stray frame and run of noise, and the counts.");
        command.Add(port);
        command.Add(hostPort);
        command.Add(plcPort);
        line.AddTo(command);
        foreach (Option o in new Option[] { capture, duration, count, summaryEvery, json })
        {
            command.Add(o);
        }

        context.SetAction(command, json, async (parse, output, ct) =>
        {
            string? one = parse.GetValue(port);
            string? host = parse.GetValue(hostPort);
            string? plc = parse.GetValue(plcPort);
            if (one is not null == (host is not null || plc is not null) || (host is null != (plc is null)))
            {
                throw new UsageException(one is null && host is null && plc is null
                    ? "Say where to listen: --port <name> for a half-duplex line, or --host-port <name> and --plc-port <name> for the two receive taps of an RS-232 line."
                    : "Give either --port, or both --host-port and --plc-port.");
            }

            string[] names = one is not null ? [one] : [host!, plc!];
            SerialLineSettings[] settings = names.Select(n => line.Settings(parse, n)).ToArray();
            CaptureWriter? writer = null;
            if (parse.GetValue(capture) is { } file)
            {
                try
                {
                    writer = CaptureWriter.Create(file);
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    throw new UsageException($"--capture: cannot create '{file}': {e.Message}", e);
                }
            }

            var chunks = Channel.CreateUnbounded<TapChunk>(new UnboundedChannelOptions { SingleReader = true });
            var taps = new List<SerialTap>();
            var clock = new MonitorClock();
            var stats = new LineStatistics();
            int? maxExchanges = parse.GetValue(count);
            TimeSpan? stopAfter = parse.GetValue(duration);
            TimeSpan every = parse.GetValue(summaryEvery) ?? TimeSpan.FromSeconds(10);
            try
            {
                for (int i = 0; i < settings.Length; i++)
                {
                    taps.Add(await SerialTap.OpenAsync(i, settings[i], chunks.Writer, ct).ConfigureAwait(false));
                }

                output.Note(names.Length == 1
                    ? $"Listening to {settings[0]} (both directions; nothing is sent). Ctrl+C stops."
                    : $"Listening to the host on {settings[0]} and the PLC on {settings[1]} (nothing is sent). Ctrl+C stops.");
                var monitor = new LineMonitor(
                    names.Length == 2,
                    clock,
                    writer,
                    e =>
                    {
                        stats.Count(e);
                        Write(output, clock, e);
                    },
                    readersProveQuiet: taps.TrueForAll(t => t.ProvesQuiet));
                long started = Stopwatch.GetTimestamp();
                using var ticker = new Timer(_ => chunks.Writer.TryWrite(new TapChunk(-1, [], Stopwatch.GetTimestamp(), 0)), null, TickInterval, TickInterval);

                // Pairing, capturing and printing run on a thread of their own, with the readers' scheduling (see
                // RealTimeScheduling): a collection this work needs runs on it, and the readers wait for it to end.
                var finished = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
                var consumer = new Thread(() =>
                {
                    try
                    {
                        RealTimeScheduling.TryRaiseThisThread();
                        Consume(chunks.Reader, monitor, output, stats, started, every, stopAfter, maxExchanges, ct);
                        finished.SetResult();
                    }
                    catch (Exception e)
                    {
                        finished.SetException(e);
                    }
                })
                {
                    IsBackground = true,
                    Name = "hostlink monitor-line",
                };
                consumer.Start();
                await finished.Task.ConfigureAwait(false);
                if (taps.FirstOrDefault(t => t.Failure is not null) is { } failed)
                {
                    throw new HostLinkConnectionException($"Lost {failed.Description}: {failed.Failure!.Message.TrimEnd('.')}.", failed.Failure);
                }
            }
            finally
            {
                foreach (SerialTap tap in taps)
                {
                    tap.Dispose();
                }

                writer?.Dispose();
            }

            return ExitCodes.Success;
        });
        return command;
    }

    /// <summary>Takes the chunks as they come until stopped, then reports what is left and the counts.</summary>
    private static void Consume(ChannelReader<TapChunk> chunks, LineMonitor monitor, OutputWriter output, LineStatistics stats, long started, TimeSpan every, TimeSpan? stopAfter, int? maxExchanges, CancellationToken ct)
    {
        long nextSummary = every > TimeSpan.Zero ? started + Ticks(every) : long.MaxValue;
        try
        {
            while (true)
            {
                if (!chunks.TryRead(out TapChunk chunk))
                {
                    if (!chunks.WaitToReadAsync(ct).AsTask().GetAwaiter().GetResult())
                    {
                        break;
                    }

                    continue;
                }

                if (chunk.Source < 0)
                {
                    monitor.Tick(chunk.Ticks);
                }
                else
                {
                    monitor.Take(chunk);
                }

                if (chunk.Ticks >= nextSummary)
                {
                    Summary(output, stats, Stopwatch.GetElapsedTime(started), final: false);
                    nextSummary += Ticks(every);
                }

                if ((stopAfter is { } d && Stopwatch.GetElapsedTime(started) >= d) || (maxExchanges is { } max && stats.Exchanges >= max))
                {
                    break;
                }
            }
        }
        catch (OperationCanceledException) when (ct.IsCancellationRequested)
        {
            // Ctrl+C: the counts so far, and a clean exit.
        }
        catch (HostLinkConnectionException)
        {
            // A port was lost: what was heard until then is reported before the loss is.
        }

        monitor.Flush(Stopwatch.GetTimestamp());
        Summary(output, stats, Stopwatch.GetElapsedTime(started), final: true);
    }

    private static long Ticks(TimeSpan t) => (long)(t.TotalSeconds * Stopwatch.Frequency);

    private static void Summary(OutputWriter output, LineStatistics stats, TimeSpan elapsed, bool final)
    {
        if (output.IsJson)
        {
            output.Result(_ => { }, j => stats.Write(j, elapsed));
            return;
        }

        foreach (string line in stats.Lines(elapsed))
        {
            if (final)
            {
                output.Line(line);
            }
            else
            {
                output.Note(line);
            }
        }
    }

    private static void Write(OutputWriter output, MonitorClock clock, MonitorEvent e)
    {
        switch (e)
        {
            case MonitorEvent.Exchanged { Exchange: var x }:
                output.Result(w => w.WriteLine(Human(clock, x)), j => Json(j, clock, x));
                break;
            case MonitorEvent.Stray { Frame: var f }:
                output.Result(
                    w => w.WriteLine($"{Time(clock, f.LastTicks)}  stray {Direction(f)} frame, in no exchange: {f.Text}{(f.Fault is { } fault ? $" ({fault})" : "")}"),
                    j => Record(j, clock, "stray", f));
                break;
            case MonitorEvent.Noise { Frame: var n }:
                output.Result(
                    w => w.WriteLine($"{Time(clock, n.LastTicks)}  {n.Bytes.Length} byte{(n.Bytes.Length == 1 ? "" : "s")} that do not frame{(n.Direction == LineDirection.Unknown ? "" : $" ({Direction(n)})")}: {Sample(n)}"),
                    j => Record(j, clock, "noise", n));
                break;
        }
    }

    /// <summary><c>09:14:02.118421  unit 00  RD  00      2.951 ms  ok</c>.</summary>
    internal static string Human(MonitorClock clock, MonitoredExchange x)
    {
        string unit = x.Unit >= 0 ? x.Unit.ToString("D2", CultureInfo.InvariantCulture) : x.Header == "**" ? "--" : "??";
        string latency = x.Latency is { } l ? $"{MonitoredExchange.Milliseconds(l),9} ms" : new string(' ', 12);
        int frames = x.CommandFrames.Count + x.AnswerFrames.Count;
        string what = x.Status switch
        {
            ExchangeStatus.Ok => "ok",
            ExchangeStatus.EndCode => x.EndCode == "IC" ? "IC: command not taken" : $"end code {x.EndCodeText}",
            ExchangeStatus.Unanswered => "no answer",
            ExchangeStatus.NoAnswerExpected => "(no answer expected)",
            ExchangeStatus.Cut => "answer cut short by the host",
            _ => "damaged: " + string.Join("; ", x.Problems),
        };
        return $"{Time(clock, x.StartTicks)}  unit {unit}  {x.Header}  {x.EndCodeText,-7} {latency}  {what}{(frames > 2 ? $" ({frames} frames)" : "")}";
    }

    private static void Json(Utf8JsonWriter j, MonitorClock clock, MonitoredExchange x)
    {
        j.WriteStartObject();
        j.WriteString("time", clock.At(x.StartTicks).ToString("O", CultureInfo.InvariantCulture));
        if (x.Unit < 0)
        {
            j.WriteNull("unit");
        }
        else
        {
            j.WriteNumber("unit", x.Unit);
        }

        j.WriteString("header", x.Header);
        j.WriteString("status", x.Status switch
        {
            ExchangeStatus.Ok => "ok",
            ExchangeStatus.EndCode => "endCode",
            ExchangeStatus.Unanswered => "unanswered",
            ExchangeStatus.NoAnswerExpected => "noAnswerExpected",
            ExchangeStatus.Cut => "cut",
            _ => "damaged",
        });
        WriteNullable(j, "endCode", x.EndCode);
        WriteNullable(j, "finsEndCode", x.FinsCode);
        if (x.Latency is { } latency)
        {
            j.WriteNumber("latencyMs", Math.Round(latency.TotalMilliseconds, 3));
        }
        else
        {
            j.WriteNull("latencyMs");
        }

        j.WriteStartArray("command");
        foreach (MonitoredFrame f in x.CommandFrames)
        {
            j.WriteStringValue(f.Text);
        }

        j.WriteEndArray();
        j.WriteStartArray("answer");
        foreach (MonitoredFrame f in x.AnswerFrames)
        {
            j.WriteStringValue(f.Text);
        }

        j.WriteEndArray();
        j.WriteStartArray("problems");
        foreach (string p in x.Problems)
        {
            j.WriteStringValue(p);
        }

        j.WriteEndArray();
        j.WriteEndObject();
    }

    private static void Record(Utf8JsonWriter j, MonitorClock clock, string kind, MonitoredFrame f)
    {
        j.WriteStartObject();
        j.WriteString("time", clock.At(f.LastTicks).ToString("O", CultureInfo.InvariantCulture));
        j.WriteString(kind, f.Text);
        j.WriteString("direction", JsonLinesCaptureWriter.Name(f.Direction));
        WriteNullable(j, "problem", f.Fault);
        j.WriteEndObject();
    }

    private static void WriteNullable(Utf8JsonWriter j, string name, string? value)
    {
        if (value is null)
        {
            j.WriteNull(name);
        }
        else
        {
            j.WriteString(name, value);
        }
    }

    private static string Time(MonitorClock clock, long ticks) => clock.At(ticks).ToLocalTime().ToString("HH:mm:ss.ffffff", CultureInfo.InvariantCulture);

    private static string Direction(MonitoredFrame f) => f.Direction switch
    {
        LineDirection.ToPlc => "host",
        LineDirection.FromPlc => "PLC",
        _ => "unknown",
    };

    private static string Sample(MonitoredFrame f)
        => f.Bytes.Length <= 32 ? f.Text : Protocol.FrameText.Printable(f.Bytes.AsSpan(0, 32)) + "…";
}
