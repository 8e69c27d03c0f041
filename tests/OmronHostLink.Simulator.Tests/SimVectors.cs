
namespace OmronHostLink.Simulator.Tests;

/// <summary>One golden vector, as the simulator tests use it.</summary>
internal sealed record SimVector(string Name, string Direction, IReadOnlyList<string> Frames, bool FcsOk, string Notes)
{
    public override string ToString() => Name;
}

/// <summary>The golden vectors (loaded by <see cref="GoldenVectors"/>) in the shape the simulator tests use.</summary>
internal static class SimVectors
{
    public static string Path => GoldenVectors.FilePath;

    public static IReadOnlyList<SimVector> Vectors { get; } =
        GoldenVectors.All.Select(v => new SimVector(v.Name, v.Direction, v.Frames, v.FcsOk, v.Notes ?? string.Empty)).ToList();

    public static SimVector Get(string name) => Vectors.Single(v => v.Name == name);
}
