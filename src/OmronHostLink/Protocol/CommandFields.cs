namespace OmronHostLink.Protocol;

/// <summary>
/// Where a command table's row puts the fields it decodes from a command or an answer, for a diagnostic view
/// (the console's <c>explain</c>). Values are string, long, bool, string[], long[], bool[],
/// <see cref="Fins.FinsAddressField"/>, <see cref="Fins.FinsAddressField"/>[] or null.
/// </summary>
internal interface ICommandFields
{
    /// <summary>Whether the frame described is the last of its message.</summary>
    bool Final { get; }

    /// <summary>Adds a decoded field.</summary>
    void Field(string name, object? value);

    /// <summary>Adds a note: something worth knowing that is not a fault.</summary>
    void Note(string note);

    /// <summary>Adds a problem: the frame is not what the protocol allows.</summary>
    void Problem(string problem);
}
