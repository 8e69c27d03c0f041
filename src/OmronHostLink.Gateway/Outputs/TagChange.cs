namespace OmronHostLink.Gateway.Outputs;

/// <summary>The outcome of reading one tag (a poll group): its value and how far it can be trusted.</summary>
/// <param name="Link">The link's configured name.</param>
/// <param name="Unit">The PLC's Host Link unit number, 0–31.</param>
/// <param name="Tag">The tag's configured name (the poll group's name).</param>
/// <param name="Address">The first address, CX-Programmer style (<c>D100</c>, <c>CIO10.03</c>).</param>
/// <param name="Type">How the words are read.</param>
/// <param name="Value">
/// The value, typed for JSON: a number, a string or a bool, or an array of them when the tag has several values (see
/// <see cref="TagValueCodec.Decode"/>). For <see cref="TagQuality.Stale"/> and <see cref="TagQuality.CommError"/> it
/// may be null: the last value read stands.
/// </param>
/// <param name="Quality">Good, stale or comm-error.</param>
/// <param name="Time">For a good value, when it was read from the PLC (UTC); otherwise when the read failed.</param>
/// <param name="Error">Why the tag could not be read; null for a good value.</param>
public sealed record TagChange(
    string Link,
    int Unit,
    string Tag,
    string Address,
    PlcValueType Type,
    object? Value,
    TagQuality Quality,
    DateTimeOffset Time,
    string? Error = null);
