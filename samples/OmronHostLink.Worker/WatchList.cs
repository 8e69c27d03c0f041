namespace OmronHostLink.Samples.Worker;

/// <summary>The <c>Watch</c> section: for each client (by its name under <c>HostLink:Clients</c>), what to poll.</summary>
public sealed class WatchList : Dictionary<string, WatchSettings>
{
    /// <summary>Creates an empty list; client names compare as configuration keys do, ignoring case.</summary>
    public WatchList()
        : base(StringComparer.OrdinalIgnoreCase)
    {
    }
}

/// <summary>What one client polls.</summary>
public sealed class WatchSettings
{
    /// <summary>From the start of one poll to the start of the next.</summary>
    public TimeSpan Interval { get; set; } = TimeSpan.FromSeconds(1);

    /// <summary>Typed tags, <c>D100:int16</c>, <c>D200:float</c>, <c>CIO10.03</c>; one planned read polls them all.</summary>
    public List<string> Tags { get; set; } = [];
}
