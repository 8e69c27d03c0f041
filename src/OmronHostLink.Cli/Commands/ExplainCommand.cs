using System.CommandLine;
using System.Globalization;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>explain</c>: decodes a captured frame. Exit 0 for a valid frame, 2 for a damaged or malformed one.</summary>
internal static class ExplainCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("explain", "Decode a captured frame: unit, header, end code and meaning, fields, FCS expected vs found. Takes the frame with or without *, CR or a literal \\r. Exit 2 when the frame is not valid.");
        var frame = new Argument<string>("frame") { Description = "The frame, for example '@00RD0000001057*' (quote it: * and $ mean something to the shell)." };
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
            FrameExplanation x = FrameExplainer.Explain(parse.GetValue(frame)!, direction);
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
