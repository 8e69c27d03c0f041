namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// The tests that start Mosquitto run one at a time: each starts its own broker, simulator and worker, and together
/// they would crowd two cores enough to blur their timings.
/// </summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class MosquittoCollection
{
    /// <summary>The collection's name.</summary>
    public const string Name = "Mosquitto";
}
