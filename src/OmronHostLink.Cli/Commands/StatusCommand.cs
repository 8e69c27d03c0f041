using System.CommandLine;
using System.Text.Json;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>status</c>: MS: operating mode, status word, FAL/FALS message.</summary>
internal static class StatusCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("status", "Operating mode (PROGRAM / MONITOR / RUN), status flags and any FAL/FALS message (MS).");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        Option<bool> json = CliContext.JsonOption();
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            await using HostLinkClient client = connection.CreateClient(parse, output);
            PlcStatus status = await client.ReadStatusAsync(ct).ConfigureAwait(false);
            output.Result(w => WriteHuman(w, client.UnitNumber, status), j => WriteJson(j, client.UnitNumber, status));
            return ExitCodes.Success;
        });
        return command;
    }

    public static string ModeName(PlcMode mode) => mode.ToString().ToUpperInvariant();

    public static void WriteHuman(TextWriter w, int unit, PlcStatus status)
    {
        w.WriteLine($"Unit {unit:D2}");
        w.WriteLine($"  Mode:                 {ModeName(status.Mode)}");
        if (status.StatusWord is { } word)
        {
            w.WriteLine($"  Status word:          {Numbers.Hex(word)} ({word})");
            w.WriteLine($"  User memory writable: {(status.UserMemoryWritable == true ? "yes" : "no (write-protected)")}");
        }
        else
        {
            w.WriteLine("  Status word:          not reported (FINS CONTROLLER STATUS READ has none)");
            w.WriteLine("  User memory writable: not reported");
        }

        w.WriteLine($"  FAL/FALS message:     {(string.IsNullOrEmpty(status.Message) ? "(none)" : status.Message)}");
    }

    public static void WriteJson(Utf8JsonWriter j, int unit, PlcStatus status)
    {
        j.WriteStartObject();
        j.WriteNumber("unit", unit);
        j.WriteString("mode", ModeName(status.Mode));
        if (status.StatusWord is { } word)
        {
            j.WriteNumber("statusWord", word);
            j.WriteBoolean("userMemoryWritable", status.UserMemoryWritable == true);
        }
        else
        {
            // Not reported by the FINS status read: null, not a guess.
            j.WriteNull("statusWord");
            j.WriteNull("userMemoryWritable");
        }
        if (string.IsNullOrEmpty(status.Message))
        {
            j.WriteNull("message");
        }
        else
        {
            j.WriteString("message", status.Message);
        }

        j.WriteEndObject();
    }
}
