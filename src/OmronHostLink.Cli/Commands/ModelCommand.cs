using System.CommandLine;
using System.Globalization;
using System.Text.Json;

namespace OmronHostLink.Cli.Commands;

/// <summary>
/// <c>model</c>: what a PLC model has and accepts. <c>model NAME</c> prints a profile, <c>model --list</c> lists them, and
/// with a connection it asks the PLC (MM) and prints the profile its code names.
/// </summary>
internal static class ModelCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("model", "PLC model: its areas, ranges and commands (a name, --list, or MM read from the PLC).");
        var name = new Argument<string?>("name") { Description = "A model (CPM1A, C200HS, CP1E-E, CS1, ...) to describe without a PLC.", Arity = ArgumentArity.ZeroOrOne };
        var list = new Option<bool>("--list") { Description = "List the known models." };
        command.Add(name);
        command.Add(list);
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        Option<bool> json = CliContext.JsonOption();
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            if (parse.GetValue(list))
            {
                output.Result(
                    w =>
                    {
                        foreach (PlcModelProfile p in PlcModelProfile.All)
                        {
                            string code = p.ModelCode is { } c ? c.ToString("X2", CultureInfo.InvariantCulture) : "??";
                            w.WriteLine($"{p.Name,-12} MM {code}  {p.DisplayName}");
                        }
                    },
                    j =>
                    {
                        j.WriteStartArray();
                        foreach (PlcModelProfile p in PlcModelProfile.All)
                        {
                            WriteProfile(j, p);
                        }

                        j.WriteEndArray();
                    });
                return ExitCodes.Success;
            }

            if (parse.GetValue(name) is { } modelName)
            {
                if (!PlcModelProfile.TryParse(modelName, out PlcModelProfile? profile))
                {
                    throw new UsageException($"'{modelName}' is not a known PLC model; known models: {PlcModelProfile.KnownNames()}.");
                }

                output.Result(w => w.WriteLine(profile.Describe()), j => WriteProfile(j, profile));
                return ExitCodes.Success;
            }

            await using HostLinkClient client = connection.CreateClient(parse, output);
            PlcModel model = await client.ReadModelAsync(ct).ConfigureAwait(false);
            PlcModelProfile? named = PlcModelProfile.FromModelCode(model.Code);
            output.Result(
                w =>
                {
                    w.WriteLine($"Unit {client.UnitNumber:D2}: {model}");
                    if (named is not null)
                    {
                        w.WriteLine(named.Describe());
                    }
                },
                j =>
                {
                    j.WriteStartObject();
                    j.WriteNumber("unit", client.UnitNumber);
                    j.WriteString("code", model.Code.ToString("X2", CultureInfo.InvariantCulture));
                    j.WriteString("model", model.Name);
                    if (named is not null)
                    {
                        j.WritePropertyName("profile");
                        WriteProfile(j, named);
                    }

                    j.WriteEndObject();
                });
            return ExitCodes.Success;
        });
        return command;
    }

    private static void WriteProfile(Utf8JsonWriter j, PlcModelProfile profile)
    {
        j.WriteStartObject();
        j.WriteString("name", profile.Name);
        j.WriteString("family", profile.DisplayName);
        if (profile.ModelCode is { } code)
        {
            j.WriteString("mmCode", code.ToString("X2", CultureInfo.InvariantCulture));
        }
        else
        {
            j.WriteNull("mmCode");
        }

        j.WriteStartArray("areas");
        foreach (PlcAreaRange range in profile.Areas)
        {
            j.WriteStartObject();
            j.WriteString("area", range.Area.ToString());
            j.WriteString("range", range.ToString());
            j.WriteBoolean("writable", range.Writable);
            j.WriteBoolean("verified", range.Verified);
            j.WriteString("source", range.Source);
            j.WriteEndObject();
        }

        j.WriteEndArray();
        j.WriteStartArray("readsZero");
        foreach (PlcAreaRange range in profile.ZeroReadRanges)
        {
            j.WriteStringValue(range.ToString());
        }

        j.WriteEndArray();
        j.WriteStartArray("cMode");
        foreach (string header in profile.CModeHeaders)
        {
            j.WriteStringValue(header);
        }

        j.WriteEndArray();
        j.WriteBoolean("fins", profile.SupportsFins);
        j.WriteBoolean("compoundRead", profile.SupportsCompoundRead);
        j.WriteString("timerCounterCoding", profile.TimerCounterCoding == TimerCounterCoding.Bcd ? "bcd" : "bcd-or-binary");
        j.WriteBoolean("sharedTimerCounterNumbers", profile.SharesTimerCounterNumbers);
        j.WriteNumber("maxFrameCharacters", profile.MaxFrameCharacters);
        j.WriteString("source", profile.Source);
        j.WriteEndObject();
    }
}
