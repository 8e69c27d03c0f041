using System.Text;
using System.Text.Json;

namespace OmronHostLink.Testing;

/// <summary>The published/constructed FCS pair of one frame of a vector.</summary>
public sealed record FcsDetail(string? Published, string? Computed);

/// <summary>One golden vector of Vectors/vectors.json (a copy of ../shared/hostlink/vectors.json).</summary>
public sealed record Vector(
    string Name,
    string Direction,
    string[] Frames,
    string Meaning,
    bool FcsOk,
    string? Source = null,
    string? PublishedOrConstructed = null,
    string? Notes = null,
    bool NoFcs = false,
    IReadOnlyList<FcsDetail>? FcsDetail = null)
{
    /// <summary>True for a host-to-PLC frame.</summary>
    public bool IsCommand => Direction == "command";

    /// <summary>True for a PLC-to-host frame.</summary>
    public bool IsResponse => Direction == "response";

    /// <summary>Whether the vector has several frames.</summary>
    public bool IsMultiFrame => Frames.Length > 1;

    /// <summary>Frame <paramref name="index"/> as the ASCII bytes on the wire.</summary>
    public byte[] FrameBytes(int index = 0) => Encoding.ASCII.GetBytes(Frames[index]);

    /// <summary>The vector's name (xUnit shows it).</summary>
    public override string ToString() => Name;
}

/// <summary>
/// Loads the golden vectors once (the repository's copy, placed beside the test assembly as Vectors/vectors.json) and serves them to
/// [MemberData] as vector names, filtered by any predicate.
/// </summary>
public static class GoldenVectors
{
    private static readonly Lazy<IReadOnlyList<Vector>> Loaded = new(Load);

    /// <summary>Where the copy of vectors.json lives.</summary>
    public static string FilePath => Path.Combine(AppContext.BaseDirectory, "Vectors", "vectors.json");

    /// <summary>Every vector, in file order.</summary>
    public static IReadOnlyList<Vector> All => Loaded.Value;

    /// <summary>The vector called <paramref name="name"/>.</summary>
    public static Vector Get(string name)
        => All.FirstOrDefault(v => v.Name == name) ?? throw new KeyNotFoundException($"No golden vector named '{name}' in {FilePath}.");

    /// <summary>The vectors that satisfy <paramref name="predicate"/>.</summary>
    public static IEnumerable<Vector> Where(Func<Vector, bool> predicate) => All.Where(predicate);

    /// <summary>[MemberData] rows of one vector name each, for the vectors that satisfy <paramref name="predicate"/>.</summary>
    public static IEnumerable<object[]> Names(Func<Vector, bool> predicate)
    {
        var rows = All.Where(predicate).Select(v => new object[] { v.Name }).ToList();
        if (rows.Count == 0)
        {
            throw new InvalidOperationException("The predicate selects no golden vector; the test would silently run nothing.");
        }

        return rows;
    }

    /// <summary>True when the vector's name starts with one of <paramref name="prefixes"/>.</summary>
    public static bool NameStartsWith(Vector vector, params string[] prefixes)
        => prefixes.Any(p => vector.Name.StartsWith(p, StringComparison.Ordinal));

    private static IReadOnlyList<Vector> Load()
    {
        if (!File.Exists(FilePath))
        {
            throw new FileNotFoundException($"Golden vectors not found at {FilePath}; the test project copies its Vectors/vectors.json there at build time.", FilePath);
        }

        using JsonDocument doc = JsonDocument.Parse(File.ReadAllBytes(FilePath));
        var vectors = new List<Vector>();
        foreach (JsonElement e in doc.RootElement.EnumerateArray())
        {
            List<FcsDetail>? details = null;
            if (e.TryGetProperty("fcs_detail", out JsonElement d) && d.ValueKind == JsonValueKind.Array)
            {
                details = d.EnumerateArray()
                    .Select(x => new FcsDetail(String(x, "fcs_published"), String(x, "fcs_computed")))
                    .ToList();
            }

            vectors.Add(new Vector(
                e.GetProperty("name").GetString()!,
                e.GetProperty("direction").GetString()!,
                e.GetProperty("frames").EnumerateArray().Select(f => f.GetString()!).ToArray(),
                String(e, "meaning") ?? string.Empty,
                e.GetProperty("fcs_ok").GetBoolean(),
                String(e, "source"),
                String(e, "published_or_constructed"),
                String(e, "notes"),
                e.TryGetProperty("no_fcs", out JsonElement nf) && nf.ValueKind == JsonValueKind.True,
                details));
        }

        return vectors;
    }

    private static string? String(JsonElement e, string property)
        => e.TryGetProperty(property, out JsonElement p) && p.ValueKind == JsonValueKind.String ? p.GetString() : null;
}
