namespace OmronHostLink.Gateway.Writes;

/// <summary>What became of a write: done (end code 00), refused before anything was sent, or failed on the line or in the PLC.</summary>
/// <param name="Status">Done, refused or failed.</param>
/// <param name="Error">Why it was refused or failed; null when done.</param>
/// <param name="EndCode">The PLC's end code when it refused the write (C-mode: two hex digits; FINS: four).</param>
internal sealed record TagWriteOutcome(TagWriteStatus Status, string? Error = null, string? EndCode = null)
{
    /// <summary>Whether the PLC took the value.</summary>
    public bool IsDone => Status == TagWriteStatus.Done;

    /// <summary>A write refused before the wire.</summary>
    public static TagWriteOutcome Refused(string error) => new(TagWriteStatus.Refused, error);
}
