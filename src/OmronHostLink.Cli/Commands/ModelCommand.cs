using System.CommandLine;
using System.Globalization;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>model</c>: MM: the PLC model code.</summary>
internal static class ModelCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("model", "PLC model (MM).");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        Option<bool> json = CliContext.JsonOption();
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            await using HostLinkClient client = connection.CreateClient(parse, output);
            PlcModel model = await client.ReadModelAsync(ct).ConfigureAwait(false);
            output.Result(
                w => w.WriteLine($"Unit {client.UnitNumber:D2}: {model}"),
                j =>
                {
                    j.WriteStartObject();
                    j.WriteNumber("unit", client.UnitNumber);
                    j.WriteString("code", model.Code.ToString("X2", CultureInfo.InvariantCulture));
                    j.WriteString("model", model.Name);
                    j.WriteEndObject();
                });
            return ExitCodes.Success;
        });
        return command;
    }
}
