namespace OmronHostLink;

/// <summary>
/// Whether planned C-mode reads (<c>ReadTagsAsync</c>, <c>WatchAsync</c>, <see cref="Planning.ReadPlanner"/>) may use
/// QQ, the compound read: scattered words and bits registered once (QQMR), then read with one short QQIR a cycle.
/// </summary>
public enum CompoundReadMode
{
    /// <summary>
    /// The default: QQ for a unit whose model profile lists it (<see cref="PlcModelProfile.SupportsCompoundRead"/>) —
    /// the configured model, or the one the unit names when asked MM once (also when no model is configured; a watch
    /// asks after its first successful cycle); area reads for a unit whose model lacks QQ or is not known (MM refused,
    /// or a code no profile has).
    /// </summary>
    Auto,

    /// <summary>QQ for every unit except one whose model profile (configured or detected) is known to lack it; MM is not asked for it.</summary>
    On,

    /// <summary>Area reads only.</summary>
    Off,
}
