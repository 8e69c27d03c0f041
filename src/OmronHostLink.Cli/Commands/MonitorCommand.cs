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
        var polls = new Option<int?>("--count") { Description = "Stop after this many polls.", HelpName = "N" };
        Option<bool> json = CliContext.JsonOption("Print one JSON document per line for each poll that saw a change.");
        command.Add(address);
        command.Add(count);
        command.Add(kind);
        command.Add(interval);
        command.Add(polls);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            ReadRequest request = ReadCommand.Request(parse, address, count, kind, connection);
            TimeSpan every = parse.GetValue(interval) ?? TimeSpan.FromSeconds(1);
            int? limit = parse.GetValue(polls);
            if (limit is < 1)
            {
                throw new UsageException($"--count must be at least 1; {limit} is not.");
            }

            await using HostLinkClient client = connection.CreateClient(parse, output);
            Snapshot? previous = null;
            int done = 0;
            try
            {
                while (limit is null || done < limit)
                {
                    if (done > 0 && every > TimeSpan.Zero)
                    {
                        await Task.Delay(every, ct).ConfigureAwait(false);
                    }

                    done++;
                    Snapshot current;
                    try
                    {
                        current = await request.ReadAsync(client, ct).ConfigureAwait(false);
                    }
                    catch (Exception e) when (previous is not null && e is HostLinkTimeoutException or HostLinkFrameException)
                    {
                        // One lost poll does not end a watch that has already started; the next poll tries again.
                        output.Note($"{Now()} {CliContext.Describe(e)}");
                        continue;
                    }

                    var changed = Enumerable.Range(0, current.ValueCount).Where(i => current.Differs(previous, i)).ToList();
                    previous = current;
                    if (changed.Count == 0)
                    {
                        continue;
                    }

                    string time = Now();
                    output.Result(
                        w =>
                        {
                            var lines = new StringWriter();
                            ReadCommand.WriteHuman(lines, current, changed);
                            foreach (string line in lines.ToString().Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries))
                            {
                                w.WriteLine($"{time}  {line}");
                            }
                        },
                        j =>
                        {
                            j.WriteStartObject();
                            j.WriteString("time", DateTimeOffset.Now.ToString("O", CultureInfo.InvariantCulture));
                            j.WriteNumber("unit", client.UnitNumber);
                            current.WriteJsonFields(j, changed);
                            j.WriteEndObject();
                        });
                }
            }
            catch (OperationCanceledException) when (ct.IsCancellationRequested)
            {
                // Ctrl+C: the normal way to stop.
            }

            return ExitCodes.Success;
        });
        return command;
    }

    private static string Now() => DateTime.Now.ToString("HH:mm:ss.fff", CultureInfo.InvariantCulture);
}
