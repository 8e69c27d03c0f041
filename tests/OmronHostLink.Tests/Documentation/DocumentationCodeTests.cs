using System.Text.RegularExpressions;

namespace OmronHostLink.Tests.Documentation;

/// <summary>
/// Every code block of docs/migrating.md and the README's VB.NET quick start is copied from code that compiles (and,
/// for the guide, runs against the simulator in OmronHostLink.VisualBasic.Tests): each block must match, line for line
/// and word for word, a run of lines of one of those files. Indentation is ignored; anything else that differs fails.
/// </summary>
public sealed partial class DocumentationCodeTests
{
    private static readonly string Root = RepositoryRoot.Path;

    private static readonly string[] CompiledFolders =
    [
        "tests/OmronHostLink.VisualBasic.Tests",
        "samples/OmronHostLink.VisualBasic.Sample",
    ];

    [Fact]
    public void Every_code_block_of_the_migration_guide_is_copied_from_compiled_VB_code()
    {
        List<(string Language, string[] Lines, int Line)> blocks = Blocks(Path.Combine(Root, "docs", "migrating.md"));

        blocks.Should().HaveCountGreaterThan(5);
        blocks.Where(b => b.Language != "vb").Select(b => $"line {b.Line}: ```{b.Language}")
            .Should().BeEmpty("every block of the guide is VB.NET, copied from compiled code");
        AssertCopied(blocks, "docs/migrating.md");
    }

    [Fact]
    public void The_README_VB_quick_start_is_copied_from_the_compiled_sample()
    {
        List<(string Language, string[] Lines, int Line)> blocks = Blocks(Path.Combine(Root, "README.md"))
            .Where(b => b.Language == "vb")
            .ToList();

        blocks.Should().ContainSingle("the README has one VB.NET quick start");
        AssertCopied(blocks, "README.md");
    }

    [Fact]
    public void A_block_that_differs_from_the_compiled_code_is_caught()
    {
        string[] copied = ["Using plc = HostLinkClient.ForSerialPort(\"COM3\")                ' 9600 7E2, unit 00 (Omron defaults)"];
        string[] changed = ["Using plc = HostLinkClient.ForSerialPort(\"COM4\")                ' 9600 7E2, unit 00 (Omron defaults)"];

        FindIn(copied).Should().NotBeNull();
        FindIn(changed).Should().BeNull();
    }

    private static void AssertCopied(IEnumerable<(string Language, string[] Lines, int Line)> blocks, string document)
    {
        var missing = new List<string>();
        foreach ((string _, string[] lines, int line) in blocks)
        {
            if (FindIn(lines) is null)
            {
                missing.Add($"{document} line {line}: {lines.FirstOrDefault()}");
            }
        }

        missing.Should().BeEmpty("each block must match a run of lines of a compiled file in {0}", string.Join(" or ", CompiledFolders));
    }

    /// <summary>The compiled file whose lines contain <paramref name="block"/> as a run, indentation aside; null when none does.</summary>
    private static string? FindIn(string[] block)
    {
        string[] wanted = block.Select(Normalise).ToArray();
        foreach (string folder in CompiledFolders)
        {
            foreach (string file in Directory.EnumerateFiles(Path.Combine(Root, folder), "*.vb", SearchOption.AllDirectories))
            {
                string[] lines = File.ReadAllLines(file).Select(Normalise).Where(l => l.Length > 0).ToArray();
                for (int start = 0; start + wanted.Length <= lines.Length; start++)
                {
                    if (lines.AsSpan(start, wanted.Length).SequenceEqual(wanted))
                    {
                        return file;
                    }
                }
            }
        }

        return null;
    }

    private static string Normalise(string line) => line.Trim();

    /// <summary>The fenced code blocks of a Markdown file: language, lines, and the line the fence opens on.</summary>
    private static List<(string Language, string[] Lines, int Line)> Blocks(string path)
    {
        string[] lines = File.ReadAllLines(path);
        var blocks = new List<(string, string[], int)>();
        for (int i = 0; i < lines.Length; i++)
        {
            Match open = Fence().Match(lines[i]);
            if (!open.Success)
            {
                continue;
            }

            int first = i + 1;
            int end = first;
            while (end < lines.Length && lines[end].Trim() != "```")
            {
                end++;
            }

            blocks.Add((open.Groups[1].Value, lines[first..end].Where(l => l.Trim().Length > 0).ToArray(), i + 1));
            i = end;
        }

        return blocks;
    }


    [GeneratedRegex(@"^\s*```(\w*)\s*$")]
    private static partial Regex Fence();
}
