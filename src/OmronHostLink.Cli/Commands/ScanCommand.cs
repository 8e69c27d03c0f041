using System.CommandLine;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>scan</c>: probes unit numbers with MM and MS and lists those that answer.</summary>
internal static class ScanCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("scan", "Probe each unit number (short timeout); print the unit, model and mode of each that answers. Exit 4 when none answers.");
        var connection = new ConnectionOptions(includeUnit: false, defaultTimeoutMs: 100, defaultRetries: 1);
        connection.AddTo(command);
        var units = new Option<string>("--units") { Description = "Unit numbers to probe: 0-31, 0,1,5 or 0-3,7.", DefaultValueFactory = _ => "0-31", HelpName = "list" };
        Option<bool> json = CliContext.JsonOption();
        command.Add(units);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            IReadOnlyList<int> list = Numbers.ParseUnits(parse.GetValue(units)!, "--units");
            await using HostLinkClient client = connection.CreateClient(parse, output);
            var found = new List<(int Unit, PlcModel? Model, PlcStatus? Status, string? Error)>();
            foreach (int unit in list)
            {
                HostLinkUnit plc = client.Unit(unit);
                try
                {
                    PlcModel model = await plc.ReadModelAsync(ct).ConfigureAwait(false);
                    PlcStatus? status = null;
                    string? error = null;
                    try
                    {
                        status = await plc.ReadStatusAsync(ct).ConfigureAwait(false);
                    }
                    catch (HostLinkEndCodeException e)
                    {
                        error = e.Message;
                    }

                    found.Add((unit, model, status, error));
                }
                catch (HostLinkEndCodeException e)
                {
                    // It answered, if only to refuse: someone is there.
                    found.Add((unit, null, null, e.Message));
                }
                catch (Exception e) when (e is HostLinkTimeoutException or HostLinkFrameException)
                {
                    if (output.Verbose)
                    {
                        output.Note($"Unit {unit:D2}: no answer ({e.Message})");
                    }
                }
            }

            output.Result(
                w =>
                {
                    if (found.Count == 0)
                    {
                        return;
                    }

                    foreach (var f in found)
                    {
                        string mode = f.Status is null ? "mode unknown" : f.Status.Mode.ToString().ToUpperInvariant();
                        string model = f.Model?.ToString() ?? "model unknown";
                        w.WriteLine(f.Error is null ? $"Unit {f.Unit:D2}: {model}, {mode}" : $"Unit {f.Unit:D2}: {model}, {mode} ({f.Error})");
                    }
                },
                j =>
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
                    j.WriteEndObject();
                });
            if (found.Count == 0)
            {
                output.Fail($"No unit answered on {client.Description} (probed {list.Count} unit numbers).");
                return ExitCodes.Communication;
            }

            return ExitCodes.Success;
        });
        return command;
    }
}
