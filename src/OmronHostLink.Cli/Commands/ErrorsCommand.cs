using System.CommandLine;
using System.Text.Json;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>errors</c>: MF: the error information words and the bits that are on.</summary>
internal static class ErrorsCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("errors", "Error information (MF): the two error words and the bits that are on; --clear clears the errors after reading. Exit 5 when an error bit is on.");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        var clear = new Option<bool>("--clear") { Description = "Clear the errors after reading them." };
        Option<bool> json = CliContext.JsonOption();
        command.Add(clear);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            bool c = parse.GetValue(clear);
            await using HostLinkClient client = connection.CreateClient(parse, output);
            PlcErrorInfo errors = await client.ReadErrorsAsync(c, ct).ConfigureAwait(false);
            output.Result(w => WriteHuman(w, client.UnitNumber, errors, c), j => WriteJson(j, client.UnitNumber, errors, c));
            return errors.HasErrors ? ExitCodes.PlcErrors : ExitCodes.Success;
        });
        return command;
    }

    public static void WriteHuman(TextWriter w, int unit, PlcErrorInfo errors, bool cleared)
    {
        if (!errors.HasErrors)
        {
            w.WriteLine($"Unit {unit:D2}: no errors (error words {Numbers.Hex(errors.FirstWord)} {Numbers.Hex(errors.SecondWord)}).");
            return;
        }

        w.WriteLine($"Unit {unit:D2}: error words {Numbers.Hex(errors.FirstWord)} ({errors.FirstWord}) {Numbers.Hex(errors.SecondWord)} ({errors.SecondWord})");
        foreach ((int word, int bit) in errors.ActiveBits)
        {
            w.WriteLine($"  word {word} bit {bit:D2} is on");
        }

        w.WriteLine("  (the meaning of each bit depends on the CPU model: see its operation manual, MF / ERROR READ)");
        if (cleared)
        {
            w.WriteLine("Errors cleared.");
        }
    }

    public static void WriteJson(Utf8JsonWriter j, int unit, PlcErrorInfo errors, bool cleared)
    {
        j.WriteStartObject();
        j.WriteNumber("unit", unit);
        j.WriteBoolean("hasErrors", errors.HasErrors);
        j.WriteStartArray("words");
        j.WriteNumberValue(errors.FirstWord);
        j.WriteNumberValue(errors.SecondWord);
        j.WriteEndArray();
        j.WriteStartArray("bits");
        foreach ((int word, int bit) in errors.ActiveBits)
        {
            j.WriteStartObject();
            j.WriteNumber("word", word);
            j.WriteNumber("bit", bit);
            j.WriteEndObject();
        }

        j.WriteEndArray();
        j.WriteBoolean("cleared", cleared);
        j.WriteEndObject();
    }
}
