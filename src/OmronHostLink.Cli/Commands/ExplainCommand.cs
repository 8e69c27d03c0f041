using System.CommandLine;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>explain</c>: decodes a captured frame. Exit 0 for a valid frame, 2 for a damaged or malformed one.</summary>
internal static class ExplainCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("explain", "Decode a captured frame: unit, header, end code and meaning, fields, FCS expected vs found. Takes the frame with or without *, CR or a literal \\r. Exit 2 when the frame is not valid.");
        var frame = new Argument<string>("frame") { Description = "The frame, for example '@00RD0000001057*' (quote it: * and $ mean something to the shell)." };
        var response = new Option<bool>("--response") { Description = "The frame is an answer from the PLC (default: a command to it)." };
        Option<bool> json = CliContext.JsonOption();
        command.Add(frame);
        command.Add(response);
        command.Add(json);
        context.SetAction(command, json, (parse, output, _) =>
        {
            FrameExplanation x = FrameExplainer.Explain(parse.GetValue(frame)!, parse.GetValue(response));
            output.Result(w => FrameExplainer.WriteHuman(w, x), j => FrameExplainer.WriteJson(j, x));
            if (!x.Valid)
            {
                output.Fail($"The frame is not valid: {x.Problems[0]}");
                return Task.FromResult(ExitCodes.InvalidInput);
            }

            return Task.FromResult(ExitCodes.Success);
        });
        return command;
    }
}
