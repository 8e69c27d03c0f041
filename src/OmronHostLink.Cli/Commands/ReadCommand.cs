using System.CommandLine;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>read</c>: reads words, numbers, text or bits.</summary>
internal static class ReadCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("read", "Read memory: words (default), BCD, 16/32-bit integers, REAL, text or bits. Any number of words is one command and one consistent snapshot.");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        var address = new Argument<string>("address") { Description = "D100, CIO100.05, W30, H10, A448, T5, C7, E1_100 (quote addresses with a space: \"CIO 100\")." };
        var count = new Argument<string?>("count") { Description = "Number of values (default 1); for --as string the number of characters (default 16).", Arity = ArgumentArity.ZeroOrOne };
        Option<string?> kind = AsOption();
        Option<bool> json = CliContext.JsonOption();
        command.Add(address);
        command.Add(count);
        command.Add(kind);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            ReadRequest request = Request(parse, address, count, kind, connection);
            await using HostLinkClient client = connection.CreateClient(parse, output);
            Snapshot snapshot = await request.ReadSnapshotAsync(client, ct).ConfigureAwait(false);
            DateTimeOffset time = DateTimeOffset.Now;
            output.Result(
                w => WriteHuman(w, snapshot, null),
                j =>
                {
                    j.WriteStartObject();
                    j.WriteNumber("unit", client.UnitNumber);
                    j.WriteString("time", time);
                    snapshot.WriteJsonFields(j);
                    j.WriteEndObject();
                });
            return ExitCodes.Success;
        });
        return command;
    }

    public static Option<string?> AsOption()
    {
        return OptionValues.OptionalChoice("--as", "word, bcd, int16, uint16, int32, uint32, float, double, string or bit (default: word, or bit for a bit address); real and lreal, as CX-Programmer names them, are float and double.", "type", ValueKinds.Accepted);
    }

    /// <summary>The read described by the arguments, checked before anything is sent.</summary>
    public static ReadRequest Request(ParseResult parse, Argument<string> address, Argument<string?> count, Option<string?> kind, ConnectionOptions connection)
    {
        string a = parse.GetValue(address)!;
        string? c = parse.GetValue(count);
        if (c is not null && c.StartsWith("--", StringComparison.Ordinal))
        {
            throw new UsageException($"Unknown option '{c}'.");
        }
        PlcAddress plcAddress;
        if (Addresses.TryJoin(a, c, out PlcAddress joined))
        {
            plcAddress = joined;
            c = null;
        }
        else
        {
            plcAddress = Addresses.Parse(a);
        }

        HostLinkCommandSet protocol = parse.GetValue(connection.Fins) ? HostLinkCommandSet.Fins : HostLinkCommandSet.CMode;
        return ReadRequest.Create(plcAddress, c, parse.GetValue(kind), protocol, connection.WordOrder);
    }

    /// <summary>One line per value: address, then the value with hex and decimal.</summary>
    public static void WriteHuman(TextWriter w, Snapshot snapshot, IReadOnlyList<int>? only)
    {
        IEnumerable<int> indexes = only ?? Enumerable.Range(0, snapshot.ValueCount);
        var labels = indexes.Select(i => (i, label: snapshot.AddressOf(i).ToString())).ToList();
        int width = labels.Count == 0 ? 0 : labels.Max(l => l.label.Length);
        foreach ((int i, string label) in labels)
        {
            w.WriteLine($"{label.PadRight(width)}  {snapshot.Human(i)}");
        }
    }
}
