using System.CommandLine;
using System.Globalization;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>test</c>: TS loopback test.</summary>
internal static class TestCommand
{
    public const string DefaultText = "HOSTLINK TEST";

    public static Command Create(CliContext context)
    {
        var command = new Command("test", "Loopback test (TS): the PLC must echo the text unchanged.");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        var text = new Argument<string?>("text") { Description = "Text to echo (printable ASCII, at most 122 characters, no * or @).", Arity = ArgumentArity.ZeroOrOne };
        Option<bool> json = CliContext.JsonOption();
        command.Add(text);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            string t = parse.GetValue(text) ?? DefaultText;
            _ = new Protocol.CMode.TestCommand(t);
            await using HostLinkClient client = connection.CreateClient(parse, output);
            TimeSpan elapsed = await client.TestAsync(t, ct).ConfigureAwait(false);
            output.Result(
                w => w.WriteLine($"Unit {client.UnitNumber:D2} echoed \"{t}\" in {elapsed.TotalMilliseconds.ToString("0.0", CultureInfo.InvariantCulture)} ms."),
                j =>
                {
                    j.WriteStartObject();
                    j.WriteNumber("unit", client.UnitNumber);
                    j.WriteString("text", t);
                    j.WriteBoolean("ok", true);
                    j.WriteNumber("milliseconds", Math.Round(elapsed.TotalMilliseconds, 3));
                    j.WriteEndObject();
                });
            return ExitCodes.Success;
        });
        return command;
    }
}
