using System.CommandLine;
using System.Globalization;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>explain</c>: decodes a captured frame. Exit 0 for a valid frame, 2 for a damaged or malformed one.</summary>
internal static class ExplainCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("explain", "Decode a captured frame: unit, header, end code and meaning, fields, FCS expected vs found. Takes the frame with or without *, CR or a literal \\r, or a capture file (pcap or pcapng from monitor-line --capture, a client's trace or simulate --capture), whose frames it decodes one by one. Exit 2 when the frame is not valid.");
        var frame = new Argument<string>("frame") { Description = "The frame, for example '@00RD0000001057*' (quote it: * and $ mean something to the shell), or a capture file ending in .pcap or .pcapng." };
        var response = new Option<bool>("--response") { Description = "The frame is an answer from the PLC (default: told from the frame where it can be, else a command)." };
        var commandOption = new Option<bool>("--command") { Description = "The frame is a command to the PLC, even where it has the shape of an answer." };
        Option<bool> json = CliContext.JsonOption();
        command.Add(frame);
        command.Add(response);
        command.Add(commandOption);
        command.Add(json);
        context.SetAction(command, json, (parse, output, _) =>
        {
            bool? direction = (parse.GetValue(response), parse.GetValue(commandOption)) switch
            {
                (true, true) => throw new UsageException("Give --response or --command, not both."),
                (true, false) => true,
                (false, true) => false,
                _ => null,
            };
            string input = parse.GetValue(frame)!;
            if (IsCaptureFile(input))
            {
                return Task.FromResult(ExplainCapture(output, input, direction));
            }

            FrameExplanation x = FrameExplainer.Explain(input, direction);
            output.Result(w => WriteHuman(w, x), j => ExplainJsonContext.Write(j, x));
            if (!x.Valid)
            {
                output.Fail($"The frame is not valid: {x.Problems[0]}");
                return Task.FromResult(ExitCodes.InvalidInput);
            }

            return Task.FromResult(ExitCodes.Success);
        });
        return command;
    }

    /// <summary>Whether the argument names a capture file rather than a frame.</summary>
    private static bool IsCaptureFile(string input)
        => !input.StartsWith('@')
            && (input.EndsWith(".pcap", StringComparison.OrdinalIgnoreCase) || input.EndsWith(".pcapng", StringComparison.OrdinalIgnoreCase) || File.Exists(input));

    /// <summary>Decodes every record of a capture, in order, each with its time and the direction the recorder gave it.</summary>
    private static int ExplainCapture(OutputWriter output, string path, bool? direction)
    {
        IReadOnlyList<Capture.CapturedFrame> records;
        try
        {
            records = Capture.CaptureReader.Read(path);
        }
        catch (Exception e) when (e is FormatException or IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"{path} cannot be read as a capture: {e.Message}", e);
        }

        int invalid = 0;
        for (int i = 0; i < records.Count; i++)
        {
            Capture.CapturedFrame record = records[i];
            bool? response = direction ?? record.Direction switch
            {
                Capture.LineDirection.ToPlc => false,
                Capture.LineDirection.FromPlc => true,
                _ => null,
            };
            string time = record.Time.ToLocalTime().ToString("yyyy-MM-dd HH:mm:ss.ffffff", CultureInfo.InvariantCulture);
            string way = record.Direction switch
            {
                Capture.LineDirection.ToPlc => "host to PLC",
                Capture.LineDirection.FromPlc => "PLC to host",
                _ => "direction unknown",
            };
            FrameExplanation? x = null;
            string? plain = null;
            if ((record.Flags & Capture.CaptureFlags.NotFramed) != 0 || record.Bytes.Any(b => b > 0x7E))
            {
                plain = $"{record.Bytes.Length} byte{(record.Bytes.Length == 1 ? "" : "s")} that do not frame: {Protocol.FrameText.Printable(record.Bytes)}";
                invalid++;
            }
            else if (record.Bytes is [(byte)'\r'])
            {
                plain = record.Direction == Capture.LineDirection.FromPlc
                    ? "CR: the PLC asks for the next frame of a divided command"
                    : "CR: the host asks for the next frame of a divided answer";
            }
            else
            {
                x = FrameExplainer.Explain(new string(record.Bytes.Select(b => (char)b).ToArray()), response);
                invalid += x.Valid ? 0 : 1;
            }

            int index = i + 1;
            output.Result(
                w =>
                {
                    w.WriteLine($"#{index}  {time}  {way}");
                    if (x is null)
                    {
                        w.WriteLine("  " + plain);
                    }
                    else
                    {
                        var text = new StringWriter(CultureInfo.InvariantCulture);
                        WriteHuman(text, x);
                        foreach (string line in text.ToString().Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries))
                        {
                            w.WriteLine("  " + line);
                        }
                    }

                    w.WriteLine();
                },
                j =>
                {
                    j.WriteStartObject();
                    j.WriteNumber("index", index);
                    j.WriteString("time", record.Time.ToString("O", CultureInfo.InvariantCulture));
                    j.WriteString("direction", Capture.JsonLinesCaptureWriter.Name(record.Direction));
                    if (x is null)
                    {
                        j.WriteString("note", plain);
                    }
                    else
                    {
                        j.WritePropertyName("explanation");
                        ExplainJsonContext.Write(j, x);
                    }

                    j.WriteEndObject();
                });
        }

        output.Note($"{path}: {records.Count} record{(records.Count == 1 ? "" : "s")}, {invalid} not valid.");
        return ExitCodes.Success;
    }

    /// <summary>Prints the explanation for people.</summary>
    private static void WriteHuman(TextWriter w, FrameExplanation x)
    {
        w.WriteLine($"Frame:      {x.Frame}");
        string direction = x.IsResponse ? "response (PLC to host)" : "command (host to PLC)";
        w.WriteLine($"Direction:  {direction}{x.DirectionFrom switch
        {
            FrameExplanation.FromShape => ", told by its shape",
            FrameExplanation.FromAmbiguous => "; ambiguous, see the note",
            FrameExplanation.FromDefault => ", assumed",
            _ => string.Empty,
        }}");
        if (x.Unit is { } unit)
        {
            w.WriteLine($"Unit:       {unit:D2}");
        }

        if (x.Header is not null)
        {
            w.WriteLine($"Header:     {x.Header}{(x.Name is null ? " (unknown header)" : " - " + x.Name)}");
        }

        if (x.EndCode is not null || x.EndCodeMeaning is not null)
        {
            w.WriteLine($"End code:   {x.EndCode ?? "(none)"} - {x.EndCodeMeaning}");
        }

        if (x.Text is not null)
        {
            w.WriteLine($"Text:       {(x.Text.Length == 0 ? "(none)" : x.Text)}");
        }

        if (x.Fcs is { } fcs)
        {
            w.WriteLine($"FCS:        found {fcs.Found}, expected {fcs.Expected}: {(fcs.Ok ? "OK" : fcs.Lowercase ? "lowercase FCS (Host Link sends it in upper case)" : "MISMATCH")}");
        }

        w.WriteLine($"Ending:     {(x.Final ? "*CR (final frame)" : "CR (more frames follow)")}");
        foreach (KeyValuePair<string, object?> field in x.Fields)
        {
            w.WriteLine($"  {field.Key}: {Human(field.Value)}");
        }

        foreach (string note in x.Notes)
        {
            w.WriteLine($"Note:       {note}");
        }

        foreach (string problem in x.Problems)
        {
            w.WriteLine($"Problem:    {problem}");
        }

        w.WriteLine($"Valid:      {(x.Valid ? "yes" : "no")}");
    }

    private static string Human(object? value) => value switch
    {
        null => "(none)",
        bool b => b ? "yes" : "no",
        long[] ls => string.Join(" ", ls.Select(l => $"0x{l:X4}({l})")),
        bool[] bs => string.Join(" ", bs.Select(b => b ? "1" : "0")),
        string[] ss => string.Join(" ", ss),
        FinsAddressField[] items => string.Join(", ", items.Select(i => i.ToString())),
        string s when s.Length == 0 => "(empty)",
        _ => Convert.ToString(value, CultureInfo.InvariantCulture) ?? string.Empty,
    };
}
