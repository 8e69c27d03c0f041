namespace OmronHostLink.Cli.Tests;

/// <summary>
/// Tests that hold timestamps to a millisecond run alone, after the parallel tests of this assembly, so that its own
/// busy thread pool does not blur their measurements.
/// </summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class TimingCollection
{
    public const string Name = "Console timing";
}
