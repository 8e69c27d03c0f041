namespace OmronHostLink.Gateway.Outputs;

/// <summary>The names outputs publish for a link's and a unit's state and for a tag's quality.</summary>
internal static class StateNames
{
    /// <summary><c>online</c>, <c>comm-error</c> or <c>offline</c>.</summary>
    public static string Name(this LinkState state) => state switch
    {
        LinkState.Online => "online",
        LinkState.CommError => "comm-error",
        _ => "offline",
    };

    /// <summary><c>online</c>, <c>comm-error</c> or <c>demoted</c>.</summary>
    public static string Name(this UnitState state) => state switch
    {
        UnitState.Online => "online",
        UnitState.CommError => "comm-error",
        _ => "demoted",
    };

    /// <summary><c>good</c>, <c>stale</c> or <c>comm-error</c>.</summary>
    public static string Name(this TagQuality quality) => quality switch
    {
        TagQuality.Good => "good",
        TagQuality.Stale => "stale",
        _ => "comm-error",
    };
}
