using System.CommandLine;
using System.Globalization;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>monitor</c>: polls an address range and prints what changes until Ctrl+C or <c>--count</c> polls.</summary>
internal static class MonitorCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("monitor", "Poll memory and print the values that change (all of them on the first poll). Ctrl+C stops.");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        var address = new Argument<string>("address") { Description = "D100, CIO100.05, W30, H10, A448, T5, C7, E1_100." };
        var count = new Argument<string?>("count") { Description = "Number of values (default 1).", Arity = ArgumentArity.ZeroOrOne };
        Option<string?> kind = ReadCommand.AsOption();
        Option<TimeSpan?> interval = Durations.Option("--interval", "Time between polls; 0 polls back to back.", TimeSpan.FromSeconds(1), TimeSpan.Zero, TimeSpan.FromDays(1));
        Option<int?> polls = OptionValues.OptionalInteger("--count", "Stop after this many polls.", 1, int.MaxValue, "N");
        var all = new Option<bool>("--all") { Description = "Print every poll, not only the values that changed." };
        Option<bool> json = CliContext.JsonOption("Print one JSON document per line for each poll that saw a change (every poll with --all), and a status line when the PLC is lost or answers again.");
        command.Add(address);
        command.Add(count);
        command.Add(kind);
        command.Add(interval);
        command.Add(polls);
        command.Add(all);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            ReadRequest request = ReadCommand.Request(parse, address, count, kind, connection);
            TimeSpan every = parse.GetValue(interval) ?? TimeSpan.FromSeconds(1);
            int? limit = parse.GetValue(polls);

            bool everyPoll = parse.GetValue(all);
            await using HostLinkClient client = connection.CreateClient(parse, output);
            var watch = new Watch(output, client.UnitNumber);
            try
            {
                for (int done = 0; limit is null || done < limit; done++)
                {
                    TimeSpan wait = done == 0 ? TimeSpan.Zero : watch.IsLost ? Max(every, RetryFloor) : every;
                    if (wait > TimeSpan.Zero)
                    {
                        await Task.Delay(wait, ct).ConfigureAwait(false);
                    }

                    Snapshot current;
                    try
                    {
                        current = await request.ReadSnapshotAsync(client, ct).ConfigureAwait(false);
                    }
                    catch (Exception e) when (e is HostLinkTimeoutException or HostLinkFrameException or HostLinkConnectionException && !ct.IsCancellationRequested)
                    {
                        // The watch outlives the PLC: reported once, tried again; the client reconnects by itself.
                        watch.Lost(e);
                        continue;
                    }

                    watch.Answered();
                    var changed = Enumerable.Range(0, current.ValueCount).Where(i => current.Differs(watch.Previous, i)).ToList();
                    watch.Previous = current;
                    if (changed.Count > 0 || everyPoll)
                    {
                        Print(output, client.UnitNumber, current, changed, everyPoll);
                    }
                }
            }
            catch (Exception) when (ct.IsCancellationRequested)
            {
                // Ctrl+C: the normal way to stop, whatever the watch was doing at that moment.
                return ExitCodes.Success;
            }

            if (watch.Previous is null && watch.LastFailure is { } failure)
            {
                // Every poll failed: nothing was watched.
                output.Report(CliContext.ErrorOf(failure));
                return ExitCodes.For(failure);
            }

            return ExitCodes.Success;
        });
        return command;
    }

    /// <summary>The shortest wait between attempts while the PLC is lost (a refused connection fails at once).</summary>
    private static readonly TimeSpan RetryFloor = TimeSpan.FromMilliseconds(250);

    private static TimeSpan Max(TimeSpan a, TimeSpan b) => a > b ? a : b;

    private static void Print(OutputWriter output, int unit, Snapshot current, List<int> changed, bool everyPoll)
    {
        string time = Now();
        output.Result(
            w =>
            {
                var lines = new StringWriter();
                ReadCommand.WriteHuman(lines, current, everyPoll ? null : changed);
                foreach (string line in lines.ToString().Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries))
                {
                    w.WriteLine($"{time}  {line}");
                }
            },
            j =>
            {
                j.WriteStartObject();
                j.WriteString("time", DateTimeOffset.Now.ToString("O", CultureInfo.InvariantCulture));
                j.WriteNumber("unit", unit);
                current.WriteJsonFields(j, changed);
                j.WriteEndObject();
            });
    }

    /// <summary>Whether the PLC answers, and the one report when that changes.</summary>
    private sealed class Watch(OutputWriter output, int unit)
    {
        private DateTimeOffset? _lostSince;

        public Snapshot? Previous { get; set; }

        public Exception? LastFailure { get; private set; }

        public bool IsLost => _lostSince is not null;

        public void Lost(Exception e)
        {
            LastFailure = e;
            if (_lostSince is not null)
            {
                return;
            }

            _lostSince = DateTimeOffset.Now;
            string message = CliContext.Describe(e);
            if (output.IsJson)
            {
                output.Document(new MonitorStatusDocument(_lostSince.Value, "lost", unit, CliContext.KindOf(e), message), CliJsonContext.Console.MonitorStatusDocument);
            }
            else
            {
                output.Note($"{Now()}  unit {unit:D2} lost: {message} Trying again until it answers (Ctrl+C stops).");
            }
        }

        public void Answered()
        {
            if (_lostSince is not { } since)
            {
                return;
            }

            _lostSince = null;
            string after = Durations.Format(DateTimeOffset.Now - since);
            if (output.IsJson)
            {
                output.Document(new MonitorStatusDocument(DateTimeOffset.Now, "resumed", unit, null, $"Unit {unit:D2} answers again after {after}."), CliJsonContext.Console.MonitorStatusDocument);
            }
            else
            {
                output.Note($"{Now()}  unit {unit:D2} answers again after {after}.");
            }
        }
    }

    private static string Now() => DateTime.Now.ToString("HH:mm:ss.fff", CultureInfo.InvariantCulture);
}
