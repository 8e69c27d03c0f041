using System.CommandLine;
using System.Globalization;
using System.Text.Json;
using OmronHostLink.Planning;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Commands;

/// <summary>
/// <c>plan</c>: the reads <c>ReadTagsAsync</c> and <c>WatchAsync</c> make for a set of tags, without a PLC: the commands,
/// their characters and the least time they take at the line's speed (a gateway's tag files: <c>OmronHostLink.Gateway --plan</c>).
/// </summary>
internal static class PlanCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("plan", "Show the reads a set of tags takes (the planner's fewest commands, QQ where the model has it) and their time at the line's speed, without a PLC.");
        var tags = new Argument<string[]>("tags") { Description = "Tags: D100, D102:float, CIO10.03, T5:bit.", Arity = ArgumentArity.ZeroOrMore };
        var file = new Option<string?>("--file") { Description = "A file of tags, one a line (# starts a comment).", HelpName = "path" };
        Option<int> unit = OptionValues.Integer("--unit", "The unit of tags that name none, 0-31.", 0, 0, HostLinkUnit.MaxUnitNumber, "n");
        Option<int?> baud = OptionValues.OptionalInteger("--baud", $"Baud rate (default {new SerialLineSettings().BaudRate}).", int.MinValue, int.MaxValue, "n");
        Option<int?> dataBits = OptionValues.OptionalInteger("--data-bits", "Data bits: 7 or 8 (default 7).", int.MinValue, int.MaxValue, "7|8");
        Option<int?> stopBits = OptionValues.OptionalInteger("--stop-bits", "Stop bits: 1 or 2 (default 2).", int.MinValue, int.MaxValue, "1|2");
        var fins = new Option<bool>("--fins") { Description = "Plan FINS reads (0101, 0104) instead of C-mode." };
        var model = new Option<string?>("--model") { Description = "The PLC model (CPM1A, C200HS, CS1, ...: see 'hostlink model --list'): its memory bounds the reads, and with --compound-read auto it decides QQ.", HelpName = "name" };
        Option<string?> compound = ConnectionOptions.CompoundReadOption();
        Option<TimeSpan?> interval = Durations.Option("--interval", "A scan interval to compare the time with.", null, TimeSpan.Zero, TimeSpan.FromDays(1));
        Option<bool> json = CliContext.JsonOption();
        command.Add(tags);
        command.Add(file);
        command.Add(unit);
        command.Add(baud);
        command.Add(dataBits);
        command.Add(stopBits);
        command.Add(fins);
        command.Add(model);
        command.Add(compound);
        command.Add(interval);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            var settings = new HostLinkClientSettings
            {
                CommandSet = parse.GetValue(fins) ? HostLinkCommandSet.Fins : HostLinkCommandSet.CMode,
                Model = parse.GetValue(model),
                UseCompoundRead = ConnectionOptions.CompoundReadOf(parse.GetValue(compound)),
            };
            settings.Serial.BaudRate = parse.GetValue(baud);
            settings.Serial.DataBits = parse.GetValue(dataBits);
            settings.Serial.StopBits = (SerialStopBits?)parse.GetValue(stopBits);
            settings.Serial.PortName = "plan"; // a link is required by the settings; none is opened
            if (settings.Validate().FirstOrDefault() is { } problem)
            {
                throw new UsageException($"{problem.Key}: {problem.Message}.");
            }

            PlcTag[] planned = await TagsAsync(parse.GetValue(tags) ?? [], parse.GetValue(file), ct).ConfigureAwait(false);
            HostLinkClientOptions options = settings.ToClientOptions();
            PlcModelProfile? profile = options.Model is { } name && !name.Equals("auto", StringComparison.OrdinalIgnoreCase) ? PlcModelProfile.Parse(name) : null;
            var planner = new ReadPlanner(options.CommandSet, options.LineTiming) { UseCompoundRead = options.UseCompoundRead, Model = profile };
            ReadPlan plan = planner.Plan(planned, parse.GetValue(unit));

            // Auto without a model: QQ waits for the PLC to name its model (MM); show what it would read with then.
            ReadPlan? pending = null;
            if (options.UseCompoundRead == CompoundReadMode.Auto && profile is null && options.CommandSet == HostLinkCommandSet.CMode)
            {
                ReadPlan qq = new ReadPlanner(options.CommandSet, options.LineTiming) { UseCompoundRead = CompoundReadMode.On }.Plan(planned, parse.GetValue(unit));
                pending = qq.Reads.Any(r => r.Kind == PlannedReadKind.CModeCompound) ? qq : null;
            }

            TimeSpan? every = parse.GetValue(interval);
            output.Result(w => WriteHuman(w, planned.Length, options, profile, plan, pending, every), j => WriteJson(j, planned.Length, options, plan, pending, every));
            return ExitCodes.Success;
        });
        return command;
    }

    private static async Task<PlcTag[]> TagsAsync(string[] texts, string? file, CancellationToken cancellationToken)
    {
        var lines = new List<(string Text, string Where)>(texts.Select((t, i) => (t, $"tag {i + 1}")));
        if (file is not null)
        {
            string[] content;
            try
            {
                content = await File.ReadAllLinesAsync(file, cancellationToken).ConfigureAwait(false);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                throw new UsageException($"--file: '{file}' cannot be read: {e.Message}", e);
            }

            for (int i = 0; i < content.Length; i++)
            {
                string text = content[i].Split('#')[0].Trim();
                if (text.Length > 0)
                {
                    lines.Add((text, $"{file}, line {i + 1}"));
                }
            }
        }

        if (lines.Count == 0)
        {
            throw new UsageException("Give the tags to plan: as arguments (D100 D102:float CIO10.03), or --file with one a line.");
        }

        var parsed = new PlcTag[lines.Count];
        for (int i = 0; i < parsed.Length; i++)
        {
            try
            {
                parsed[i] = PlcTag.Parse(lines[i].Text);
            }
            catch (FormatException e)
            {
                throw new UsageException($"{lines[i].Where}: {e.Message}", e);
            }
        }

        return parsed;
    }

    private static void WriteHuman(TextWriter w, int tags, HostLinkClientOptions options, PlcModelProfile? profile, ReadPlan plan, ReadPlan? pending, TimeSpan? every)
    {
        string set = options.CommandSet == HostLinkCommandSet.Fins ? "FINS" : "C-mode";
        string model = profile is null ? "no model" : profile.DisplayName;
        w.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{tags} tag(s), {set}, {options.LineTiming}, UseCompoundRead {options.UseCompoundRead}, {model}:"));
        w.WriteLine($"{plan}{Share(plan, every)}");
        foreach (PlannedRead read in plan.Reads)
        {
            w.WriteLine($"  {read}");
        }

        if (pending is not null)
        {
            w.WriteLine($"Once the PLC names its model (MM), and where that model has QQ: {pending}{Share(pending, every)}");
            foreach (PlannedRead read in pending.Reads)
            {
                w.WriteLine($"  {read}");
            }
        }
    }

    private static void WriteJson(Utf8JsonWriter j, int tags, HostLinkClientOptions options, ReadPlan plan, ReadPlan? pending, TimeSpan? every)
    {
        j.WriteStartObject();
        j.WriteNumber("tags", tags);
        j.WriteString("commandSet", options.CommandSet == HostLinkCommandSet.Fins ? "fins" : "cmode");
        j.WriteNumber("baudRate", options.LineTiming.BaudRate);
        j.WriteString("compoundRead", options.UseCompoundRead.ToString().ToLowerInvariant());
        if (options.Model is { } model)
        {
            j.WriteString("model", model);
        }

        if (every is { } interval)
        {
            j.WriteNumber("intervalMs", interval.TotalMilliseconds);
        }

        j.WritePropertyName("plan");
        WritePlan(j, plan);
        if (pending is not null)
        {
            j.WritePropertyName("withCompoundRead");
            WritePlan(j, pending);
        }

        j.WriteEndObject();
    }

    private static void WritePlan(Utf8JsonWriter j, ReadPlan plan)
    {
        j.WriteStartObject();
        j.WriteNumber("reads", plan.TransactionCount);
        j.WriteNumber("characters", plan.Characters);
        j.WriteNumber("exchanges", plan.Exchanges);
        j.WriteNumber("estimatedMs", Math.Round(plan.EstimatedTime.TotalMilliseconds, 1));
        j.WriteStartArray("commands");
        foreach (PlannedRead read in plan.Reads)
        {
            j.WriteStartObject();
            j.WriteString("kind", read.Kind.ToString());
            j.WriteNumber("unit", read.Unit);
            if (read.Kind is not (PlannedReadKind.CModeCompound or PlannedReadKind.FinsMultiple))
            {
                j.WriteString("start", read.Start.ToString());
            }

            j.WriteNumber("count", read.Count);
            j.WriteNumber("characters", read.Characters);
            j.WriteString("text", read.ToString());
            j.WriteEndObject();
        }

        j.WriteEndArray();
        j.WriteEndObject();
    }

    private static string Share(ReadPlan plan, TimeSpan? every)
        => every is { } interval && interval > TimeSpan.Zero
            ? string.Create(CultureInfo.InvariantCulture, $" — {plan.EstimatedTime / interval:P0} of a {Durations.Format(interval)} interval{(plan.EstimatedTime > interval ? ": more than it, read every " + Durations.Format(plan.EstimatedTime) + " at best" : "")}")
            : "";
}
