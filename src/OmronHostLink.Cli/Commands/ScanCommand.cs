using System.CommandLine;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>scan</c>: probes each unit number with one short TS and lists those that answer, with model (MM) and mode (MS).</summary>
internal static class ScanCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("scan", "Probe each unit number with one short TS; print the unit, model and mode of each that answers. Exit 4 when none answers.");
        var connection = new ConnectionOptions(includeUnit: false, defaultTimeout: TimeSpan.FromMilliseconds(100), defaultRetries: 1);
        connection.AddTo(command);
        var units = new Option<string>("--units") { Description = $"Unit numbers to probe: 0-{SettingRules.MaxUnitNumber}, 0,1,5 or 0-3,7.", DefaultValueFactory = _ => $"0-{SettingRules.MaxUnitNumber}", HelpName = "list" };
        Option<bool> json = CliContext.JsonOption();
        command.Add(units);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            IReadOnlyList<int> list = Numbers.ParseUnits(parse.GetValue(units)!, "--units");
            await using HostLinkClient client = connection.CreateClient(parse, output);
            var found = new List<(int Unit, PlcModel? Model, PlcStatus? Status, string? Error)>();
            var clock = System.Diagnostics.Stopwatch.StartNew();
            var progress = new Progress(output);
            output.Note($"Scanning {Count(list.Count, "unit number")} on {client.Description}...");
            foreach (int unit in list)
            {
                progress.Show($"unit {unit:D2} ({found.Count} found)");
                HostLinkUnit plc = client.Unit(unit);

                // One short TS per unit number: a silent one costs that deadline only, with no model read and no
                // resynchronisation exchange before the next unit.
                if (await plc.ProbeAsync(cancellationToken: ct).ConfigureAwait(false) is null)
                {
                    if (output.Verbose)
                    {
                        output.Note($"Unit {unit:D2}: no answer.");
                    }

                    continue;
                }

                PlcModel? model = null;
                PlcStatus? status = null;
                string? error = null;
                try
                {
                    model = await plc.ReadModelAsync(ct).ConfigureAwait(false);
                    status = await plc.ReadStatusAsync(ct).ConfigureAwait(false);
                }
                catch (Exception e) when (e is HostLinkEndCodeException or HostLinkTimeoutException or HostLinkFrameException)
                {
                    // It answered the probe: someone is there, whatever it makes of MM or MS.
                    error = CliContext.Describe(e);
                }

                found.Add((unit, model, status, error));
                progress.Clear();
                if (!output.IsJson)
                {
                    output.Line(Describe(found[^1]));
                }
            }

            progress.Clear();
            output.Note($"Scanned {Count(list.Count, "unit number")} in {Durations.Format(clock.Elapsed)}: {Answer(found.Count)}.");
            ErrorInfo? none = found.Count == 0
                ? new ErrorInfo("timeout", null, $"No unit answered on {client.Description} (probed {Count(list.Count, "unit number")}).")
                : null;
            if (output.IsJson)
            {
                output.Result(_ => { }, j => WriteJson(j, found, none));
            }

            if (none is not null)
            {
                output.Fail(none.Message);
                return ExitCodes.Communication;
            }

            return ExitCodes.Success;
        });
        return command;
    }

    private static string Count(int n, string what) => n == 1 ? $"1 {what}" : $"{n} {what}s";

    private static string Answer(int n) => n switch
    {
        0 => "no unit answers",
        1 => "1 unit answers",
        _ => $"{n} units answer",
    };

    private static string Describe((int Unit, PlcModel? Model, PlcStatus? Status, string? Error) f)
    {
        string mode = f.Status is null ? "mode unknown" : f.Status.Mode.ToString().ToUpperInvariant();
        string model = f.Model?.ToString() ?? "model unknown";
        return f.Error is null ? $"Unit {f.Unit:D2}: {model}, {mode}" : $"Unit {f.Unit:D2}: {model}, {mode} ({f.Error})";
    }

    private static void WriteJson(System.Text.Json.Utf8JsonWriter j, List<(int Unit, PlcModel? Model, PlcStatus? Status, string? Error)> found, ErrorInfo? none)
    {
        j.WriteStartObject();
        j.WriteStartArray("units");
        foreach (var f in found)
        {
            j.WriteStartObject();
            j.WriteNumber("unit", f.Unit);
            if (f.Model is null)
            {
                j.WriteNull("modelCode");
                j.WriteNull("model");
            }
            else
            {
                j.WriteString("modelCode", f.Model.Code.ToString("X2", System.Globalization.CultureInfo.InvariantCulture));
                j.WriteString("model", f.Model.Name);
            }

            if (f.Status is null)
            {
                j.WriteNull("mode");
            }
            else
            {
                j.WriteString("mode", f.Status.Mode.ToString().ToUpperInvariant());
            }

            if (f.Error is not null)
            {
                j.WriteString("error", f.Error);
            }

            j.WriteEndObject();
        }

        j.WriteEndArray();
        if (none is not null)
        {
            // The one document of a failed scan says so as every failed command's does.
            j.WritePropertyName("error");
            System.Text.Json.JsonSerializer.Serialize(j, none, CliJsonContext.Console.ErrorInfo);
        }

        j.WriteEndObject();
    }

    /// <summary>A one-line progress indicator, redrawn in place on an interactive terminal only.</summary>
    private sealed class Progress(OutputWriter output)
    {
        private readonly bool _live = ReferenceEquals(output.Error, Console.Error) && !Console.IsErrorRedirected;
        private int _width;

        public void Show(string text)
        {
            if (_live)
            {
                string line = "  probing " + text;
                output.Error.Write("\r" + line.PadRight(_width));
                _width = line.Length;
            }
        }

        public void Clear()
        {
            if (_live && _width > 0)
            {
                output.Error.Write("\r" + new string(' ', _width) + "\r");
                _width = 0;
            }
        }
    }
}
