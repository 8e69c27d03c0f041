using System.CommandLine;

namespace OmronHostLink.Cli;

/// <summary>
/// Help as printed: the library's layout, with optional arguments shown as optional in the Arguments and Commands
/// sections too (<c>[&lt;count&gt;]</c>, as the usage line already writes them), columns kept aligned.
/// </summary>
internal static class HelpText
{
    /// <summary>Marks the optional arguments of <paramref name="command"/> and of its subcommands in <paramref name="help"/>.</summary>
    public static string MarkOptionalArguments(string help, Command command)
    {
        string newline = help.Contains("\r\n", StringComparison.Ordinal) ? "\r\n" : "\n";
        string[] lines = help.Split(newline);
        Rewrite(lines, "Arguments:", label => Optional(command).Contains(label) ? $"[{label}]" : label);
        Rewrite(lines, "Commands:", label =>
        {
            string[] words = label.Split(' ');
            Command? sub = command.Subcommands.FirstOrDefault(c => c.Name == words[0]);
            if (sub is null)
            {
                return label;
            }

            HashSet<string> optional = Optional(sub);
            return string.Join(' ', words.Select((w, i) => i > 0 && optional.Contains(w) ? $"[{w}]" : w));
        });
        return string.Join(newline, lines);
    }

    private static HashSet<string> Optional(Command command)
        => command.Arguments
            .Where(a => a.Arity.MinimumNumberOfValues == 0 && !a.Hidden)
            .Select(a => "<" + (a.HelpName ?? a.Name) + ">")
            .ToHashSet(StringComparer.Ordinal);

    /// <summary>Relabels the first column of a two-column section and moves the second column to fit.</summary>
    private static void Rewrite(string[] lines, string title, Func<string, string> relabel)
    {
        int start = Array.IndexOf(lines, title);
        if (start < 0)
        {
            return;
        }

        var rows = new List<(int Line, string Label, string Description)>();
        var continuations = new List<int>();
        int oldColumn = 0;
        for (int i = start + 1; i < lines.Length && lines[i].Length > 0; i++)
        {
            string line = lines[i];
            if (line.Length > 2 && line[2] != ' ')
            {
                int gap = line.IndexOf("  ", 2, StringComparison.Ordinal);
                int description = gap < 0 ? line.Length : gap + (line.AsSpan(gap).Length - line.AsSpan(gap).TrimStart(' ').Length);
                oldColumn = Math.Max(oldColumn, description);
                rows.Add((i, gap < 0 ? line[2..] : line[2..gap], line[description..]));
            }
            else
            {
                continuations.Add(i);
            }
        }

        if (rows.Count == 0)
        {
            return;
        }

        var labels = rows.Select(r => relabel(r.Label)).ToArray();
        int newColumn = Math.Max(oldColumn, 2 + labels.Max(l => l.Length) + 2);
        for (int r = 0; r < rows.Count; r++)
        {
            lines[rows[r].Line] = ("  " + labels[r]).PadRight(newColumn) + rows[r].Description;
        }

        foreach (int i in continuations)
        {
            lines[i] = new string(' ', newColumn - oldColumn) + lines[i];
        }
    }
}
