using System.Globalization;

namespace OmronHostLink.Benchmarks.Polling;

/// <summary>
/// A Kepware tag export of scattered words and bits, as a plant exports one: one row a tag, clusters around a few hot
/// spots and loners, in DM, HR, AR, IR and timers (present values and completion flags), every row at one scan rate.
/// </summary>
internal static class ScatteredTagFile
{
    /// <summary>One generated tag: its Kepware row and what the PLC must read for it.</summary>
    public sealed record Tag(string Name, string KepwareAddress, string KepwareType, PlcArea Area, int Word, int Words, bool CompletionFlag);

    public static Tag[] Generate(int count, int seed, string prefix = "t")
    {
        var random = new Random(seed);
        (string Kepware, PlcArea Area, int Max)[] areas =
        [
            ("DM", PlcArea.Dm, 9990), ("DM", PlcArea.Dm, 9990), ("DM", PlcArea.Dm, 9990),
            ("HR", PlcArea.Holding, 510), ("IR", PlcArea.Cio, 6000), ("AR", PlcArea.Auxiliary, 958), ("TC", PlcArea.Timer, 2046),
        ];
        var spots = Enumerable.Range(0, 12).Select(_ => areas[random.Next(areas.Length)]).Select(a => (a.Kepware, a.Area, a.Max, Word: random.Next(0, a.Max - 40))).ToArray();
        var tags = new List<Tag>();
        var used = new HashSet<(PlcArea, int, bool)>();
        while (tags.Count < count)
        {
            (string kepware, PlcArea area, int max, int word) = random.Next(4) == 0
                ? areas[random.Next(areas.Length)] is var a ? (a.Kepware, a.Area, a.Max, random.Next(0, a.Max)) : default
                : spots[random.Next(spots.Length)] is var s ? (s.Kepware, s.Area, s.Max, s.Word + random.Next(0, 40)) : default;
            word = Math.Min(word, max);
            int pick = random.Next(10);
            string name = $"{prefix}{tags.Count:D3}";
            Tag tag;
            if (area == PlcArea.Timer)
            {
                tag = pick < 4
                    ? new Tag(name, $"TC{word:D3}", "Boolean", area, word, 1, CompletionFlag: true)
                    : new Tag(name, $"TC{word:D3}", "Word", area, word, 1, CompletionFlag: false);
            }
            else if (pick < 3 && area != PlcArea.Dm)
            {
                tag = new Tag(name, $"{Address(kepware, word)}.{random.Next(16):D2}", "Boolean", area, word, 1, false);
            }
            else
            {
                (string type, int words) = pick switch
                {
                    < 4 => ("Word", 1),
                    < 6 => ("Short", 1),
                    < 8 => ("Long", 2),
                    _ => ("Float", 2),
                };
                tag = new Tag(name, Address(kepware, word), type, area, word, words, false);
            }

            if (used.Add((area, word, tag.CompletionFlag)) || tag.KepwareType == "Boolean")
            {
                tags.Add(tag);
            }
        }

        return tags.ToArray();
    }

    /// <summary>The export: Kepware's header and one row a tag, at <paramref name="scanRateMs"/>.</summary>
    public static string Csv(IEnumerable<Tag> tags, int scanRateMs)
        => KepwareTagExport.Csv(tags.Select(t => (t.Name, t.KepwareAddress, t.KepwareType)), scanRateMs);

    /// <summary>The words the PLC is asked for this tag (for a completion flag, the flag).</summary>
    public static IEnumerable<CommandLedger.ReadKey> Keys(Tag tag, int unit)
        => Enumerable.Range(0, tag.Words).Select(i => new CommandLedger.ReadKey(unit, tag.Area, 0, tag.Word + i, tag.CompletionFlag));

    private static string Address(string kepware, int word) => kepware switch
    {
        "DM" => $"DM{word:D4}",
        "IR" => $"IR{word:D3}",
        _ => $"{kepware}{word:D2}",
    };
}
