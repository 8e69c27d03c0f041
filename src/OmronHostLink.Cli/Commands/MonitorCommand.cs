using System.CommandLine;
using System.Globalization;
using System.Runtime.ExceptionServices;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>monitor</c>: polls an address range and prints what changes until Ctrl+C or <c>--count</c> polls.</summary>
internal static class MonitorCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("monitor", "Poll memory and print the values that change (all of them on the first poll). Ctrl+C stops.");
        var connection = new ConnectionOptions(plansReads: true);
        connection.AddTo(command);
        var address = new Argument<string>("address") { Description = "D100, CIO100.05, W30, H10, A448, T5, C7, E1_100." };
        var count = new Argument<string?>("count") { Description = "Number of values (default 1).", Arity = ArgumentArity.ZeroOrOne };
        Option<string?> kind = ReadCommand.AsOption();
        Option<TimeSpan?> interval = Durations.Option("--interval", "Time from the start of one poll to the start of the next; 0 polls back to back.", TimeSpan.FromSeconds(1), TimeSpan.Zero, TimeSpan.FromDays(1));
        Option<int?> polls = OptionValues.OptionalInteger("--count", "Stop after this many polls.", 1, int.MaxValue, "N");
        var all = new Option<bool>("--all") { Description = "Print every poll, not only the values that changed." };
        Option<bool> json = CliContext.JsonOption("Print one JSON document per line for each poll that saw a change (every poll with --all), and a status line when the PLC is lost or answers again (with --verbose also when a poll overruns the interval).");
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
            var values = new WatchedValues(request);

            // Every poll is reported (Polled, or a failure), so --count counts failed polls too.
            var options = new WatchOptions { Interval = every, RetryInterval = every > RetryFloor ? every : RetryFloor, ReportEveryCycle = true };
            await using HostLinkClient client = connection.CreateClient(parse, output);
            var link = new LinkReports(output, client.UnitNumber, every);
            int done = 0;
            try
            {
                await foreach (WatchEvent e in client.WatchAsync(values.Tags, options, ct).ConfigureAwait(false))
                {
                    switch (e.Kind)
                    {
                        case WatchEventKind.Changed:
                            values.Apply(e);
                            continue;
                        case WatchEventKind.Resumed:
                            link.Resumed(e);
                            continue;
                        case WatchEventKind.Overrun:
                            link.Overran(e);
                            continue;
                        case WatchEventKind.Polled:
                            link.Polled();
                            List<int> changed = values.EndPoll();
                            if (changed.Count > 0 || everyPoll)
                            {
                                Print(output, client.UnitNumber, values.Current, changed, everyPoll, e.Timestamp);
                            }

                            break;
                        default:
                            // A failure while Ctrl+C stops the watch is the stop, not an outage.
                            ct.ThrowIfCancellationRequested();
                            link.Failed(e);
                            break;
                    }

                    if (++done == limit)
                    {
                        break;
                    }
                }
            }
            catch (Exception) when (ct.IsCancellationRequested)
            {
                // Ctrl+C: the normal way to stop, whatever the watch was doing at that moment.
                return ExitCodes.Success;
            }

            if (!link.EverAnswered && link.LastFailure is { } failure)
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

    private static void Print(OutputWriter output, int unit, Snapshot current, List<int> changed, bool everyPoll, DateTimeOffset read)
    {
        string time = Clock(read);
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
                j.WriteString("time", read.ToLocalTime().ToString("O", CultureInfo.InvariantCulture));
                j.WriteNumber("unit", unit);
                current.WriteJsonFields(j, changed);
                j.WriteEndObject();
            });
    }

    /// <summary>What the watch says about the link rather than values: each outage once, its end, and overruns.</summary>
    private sealed class LinkReports(OutputWriter output, int unit, TimeSpan every)
    {
        private bool _connecting = true;
        private bool _lastPollConnected;

        public bool EverAnswered { get; private set; }

        public Exception? LastFailure { get; private set; }

        public void Polled()
        {
            EverAnswered = true;
            _lastPollConnected = _connecting;
            _connecting = false;
        }

        /// <summary>
        /// A failed poll (<see cref="WatchEventKind.Outage"/>, then <see cref="WatchEventKind.RetryFailed"/> while it
        /// lasts): the watch outlives the PLC, so the outage is reported once and tried again (the client reconnects
        /// by itself). A failure that is not the link's ends the watch.
        /// </summary>
        public void Failed(WatchEvent e)
        {
            Exception failure = e.Exception!;
            if (failure is not (HostLinkTimeoutException or HostLinkFrameException or HostLinkConnectionException))
            {
                // The PLC refused the read (an end code) or something else broke: an error, not an outage to outlive.
                ExceptionDispatchInfo.Throw(failure);
            }

            LastFailure = failure;
            _connecting = true;
            if (e.Kind == WatchEventKind.Outage)
            {
                string message = CliContext.Describe(failure);
                Report(e.Timestamp, "lost", CliContext.KindOf(failure), message, $"lost: {message} Trying again until it answers (Ctrl+C stops).");
            }
        }

        public void Resumed(WatchEvent e)
        {
            string after = Durations.Format(e.Duration);
            Report(e.Timestamp, "resumed", null, $"Unit {unit:D2} answers again after {after}.", $"answers again after {after}.");
        }

        /// <summary>
        /// A poll longer than the interval (the next starts at once): a diagnostic, with --verbose only, since a
        /// stalled machine overruns a short interval now and then. Not for the poll that opened the connection (the
        /// first, or the first after an outage): connecting is not polling.
        /// </summary>
        public void Overran(WatchEvent e)
        {
            if (_lastPollConnected || !output.Verbose)
            {
                return;
            }

            string took = $"took {Durations.Format(e.Duration)}, longer than the {Durations.Format(every)} interval; the next starts at once.";
            Report(e.Timestamp, "overrun", null, $"Unit {unit:D2}: a poll {took}", $"overrun: the poll {took}");
        }

        private void Report(DateTimeOffset time, string status, string? kind, string message, string note)
        {
            if (output.IsJson)
            {
                output.Document(new MonitorStatusDocument(time.ToLocalTime(), status, unit, kind, message), CliJsonContext.Console.MonitorStatusDocument);
            }
            else
            {
                output.Note($"{Clock(time)}  unit {unit:D2} {note}");
            }
        }
    }

    private static string Clock(DateTimeOffset time) => time.ToLocalTime().ToString("HH:mm:ss.fff", CultureInfo.InvariantCulture);
}
