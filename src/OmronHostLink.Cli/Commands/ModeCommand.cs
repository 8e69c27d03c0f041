using System.CommandLine;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>mode</c>: SC: changes the operating mode, only with <c>--yes</c>.</summary>
internal static class ModeCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("mode", "Change the operating mode (SC). Refuses without --yes: leaving RUN or MONITOR stops the machine's program.");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        Argument<string> mode = OptionValues.ChoiceArgument("mode", "run, monitor or program (any case).", "run", "monitor", "program");
        var yes = new Option<bool>("--yes") { Description = "Confirm the change." };
        Option<bool> json = CliContext.JsonOption();
        command.Add(mode);
        command.Add(yes);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            PlcMode target = parse.GetValue(mode) switch
            {
                "run" => PlcMode.Run,
                "monitor" => PlcMode.Monitor,
                _ => PlcMode.Program,
            };
            int unit = connection.GetUnit(parse);
            if (!parse.GetValue(yes))
            {
                throw new UsageException(
                    $"Refusing to change unit {unit:D2} to {StatusCommand.ModeName(target)} mode without --yes: a mode change can stop or start the machine's program; add --yes to confirm.");
            }

            await using HostLinkClient client = connection.CreateClient(parse, output);
            await client.SetModeAsync(target, ct).ConfigureAwait(false);
            PlcStatus status = await client.ReadStatusAsync(ct).ConfigureAwait(false);
            output.Result(
                w => w.WriteLine($"Unit {unit:D2} is now in {StatusCommand.ModeName(status.Mode)} mode."),
                j =>
                {
                    j.WriteStartObject();
                    j.WriteNumber("unit", unit);
                    j.WriteString("requested", StatusCommand.ModeName(target));
                    j.WriteString("mode", StatusCommand.ModeName(status.Mode));
                    j.WriteEndObject();
                });
            if (status.Mode != target)
            {
                output.Fail($"Unit {unit:D2} accepted the change but reports {StatusCommand.ModeName(status.Mode)} mode.");
                return ExitCodes.Failure;
            }

            return ExitCodes.Success;
        });
        return command;
    }
}
