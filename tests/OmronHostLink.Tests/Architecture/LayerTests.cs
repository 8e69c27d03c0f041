using System.Text.RegularExpressions;

namespace OmronHostLink.Tests.Architecture;

/// <summary>
/// The core's folders point down only: the layer table of <c>docs/architecture.md</c> (top layer first) is read as the
/// order, and the compiler's view of every name in <c>src/OmronHostLink</c> must never reach a folder of a higher layer.
/// Every folder of the core must be in the table.
/// </summary>
public partial class LayerTests
{
    private static readonly string Core = Path.Combine(SourceDependencies.SourceRoot(), "OmronHostLink");

    private static readonly Lazy<SourceDependencies> Dependencies = new(() => SourceDependencies.Of(Core));

    [Fact]
    public void Every_core_folder_is_in_the_layer_table()
    {
        IReadOnlyList<string[]> layers = DocumentedLayers();
        string[] folders = Directory.GetDirectories(Core)
            .Select(Path.GetFileName)
            .Where(f => f is not ("bin" or "obj"))
            .Append(".")
            .ToArray()!;

        folders.Except(layers.SelectMany(l => l)).Should().BeEmpty("docs/architecture.md's layer table places every folder of src/OmronHostLink");
        layers.SelectMany(l => l).Except(folders).Should().BeEmpty("the layer table names only folders that exist");
    }

    [Fact]
    public void No_core_folder_uses_one_above_it()
    {
        IReadOnlyList<string[]> layers = DocumentedLayers();
        int LayerOf(string folder) => layers.Count - 1 - layers.ToList().FindIndex(l => l.Contains(folder));

        string[] upward = Dependencies.Value.Uses
            .Where(u => LayerOf(u.ToFolder) > LayerOf(u.FromFolder))
            .Select(u => $"{u.FromFile} ({u.FromFolder}) uses {u.Name} ({u.ToFolder})")
            .Distinct()
            .ToArray();

        upward.Should().BeEmpty("a layer uses only the layers below it (docs/architecture.md)");
    }

    [Fact]
    public void The_check_sees_a_use_across_folders()
    {
        // The test must be able to fail: the link does use the transports, and the rules use nothing.
        Dependencies.Value.Uses.Should().Contain(u => u.FromFolder == "Link" && u.ToFolder == "Transports");
        Dependencies.Value.Uses.Should().NotContain(u => u.FromFolder == "Rules" && u.ToFolder != "Polyfills");
    }

    /// <summary>The folders of each row of the layer table, top layer first: the backticked names ending in <c>/</c>.</summary>
    private static IReadOnlyList<string[]> DocumentedLayers()
    {
        string doc = File.ReadAllText(Path.Combine(SourceDependencies.SourceRoot(), "..", "docs", "architecture.md"));
        string section = doc[doc.IndexOf("## Layers", StringComparison.Ordinal)..];
        section = section[..section.IndexOf("\n## ", 3, StringComparison.Ordinal)];
        return section.Split('\n')
            .Where(line => line.StartsWith('|') && !line.StartsWith("|---", StringComparison.Ordinal))
            .Select(line => line.Split('|', StringSplitOptions.RemoveEmptyEntries))
            .Where(cells => cells.Length >= 2)
            .Select(cells => FolderName().Matches(cells[1]).Select(m => m.Groups[1].Value).ToArray())
            .Where(folders => folders.Length > 0)
            .ToArray();
    }

    [GeneratedRegex(@"`([A-Za-z]+|\.)/`")]
    private static partial Regex FolderName();
}
