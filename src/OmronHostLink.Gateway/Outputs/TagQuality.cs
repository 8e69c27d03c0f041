namespace OmronHostLink.Gateway.Outputs;

/// <summary>How far a tag's value can be trusted.</summary>
public enum TagQuality
{
    /// <summary>Just read from the PLC.</summary>
    Good,

    /// <summary>
    /// The PLC answers but this tag cannot be read (an end code, a word that is not BCD): the value is the last one read.
    /// </summary>
    Stale,

    /// <summary>The tag's PLC unit does not answer: the value is the last one read.</summary>
    CommError,
}
