using System.Text.Json;

namespace OmronHostLink.Tests.Simulator;

/// <summary>One golden vector from vectors.json (a private loader for the simulator tests).</summary>
internal sealed record SimVector(string Name, string Direction, IReadOnlyList<string> Frames, bool FcsOk, string Notes)
{
    public override string ToString() => Name;
}

/// <summary>Reads the golden vectors the test project copies next to the test assembly.</summary>
internal static class SimVectors
{
    private static readonly Lazy<IReadOnlyList<SimVector>> All = new(Load);

    public static string Path => System.IO.Path.Combine(AppContext.BaseDirectory, "vectors", "vectors.json");

    public static IReadOnlyList<SimVector> Vectors => All.Value;

    public static SimVector Get(string name) => Vectors.Single(v => v.Name == name);

    private static IReadOnlyList<SimVector> Load()
    {
        using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(Path));
        var list = new List<SimVector>();
        foreach (JsonElement e in doc.RootElement.EnumerateArray())
        {
            list.Add(new SimVector(
                e.GetProperty("name").GetString()!,
                e.GetProperty("direction").GetString()!,
                e.GetProperty("frames").EnumerateArray().Select(f => f.GetString()!).ToList(),
                e.GetProperty("fcs_ok").GetBoolean(),
                e.TryGetProperty("notes", out JsonElement n) ? n.GetString() ?? string.Empty : string.Empty));
        }

        return list;
    }
}
