namespace OmronHostLink.Simulator.Tests;

/// <summary>
/// Tests that measure time on the wire run alone, after the parallel tests, so that a loaded thread pool does not
/// blur their measurements.
/// </summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class TimingCollection
{
    public const string Name = "Simulator timing";
}
