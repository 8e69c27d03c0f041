namespace OmronHostLink;

/// <summary>
/// The unit's status: the operating mode, the status word, and any FAL/FALS message. C-mode MS (STATUS READ) reports
/// all three; FINS CONTROLLER STATUS READ reports the mode and the message but no status word, so the status word and
/// what it tells (<see cref="UserMemoryWritable"/>) are null then: not reported, never guessed.
/// </summary>
public sealed class PlcStatus
{
    /// <summary>Creates the status.</summary>
    /// <param name="mode">The operating mode.</param>
    /// <param name="statusWord">The MS status word, or null when the PLC was not asked in a way that reports one.</param>
    /// <param name="message">The FAL/FALS message, or null.</param>
    public PlcStatus(PlcMode mode, ushort? statusWord, string? message)
    {
        Mode = mode;
        StatusWord = statusWord;
        Message = message;
    }

    /// <summary>The operating mode (status bits 9-8: 00 PROGRAM, 10 RUN, 11 MONITOR).</summary>
    public PlcMode Mode { get; }

    /// <summary>
    /// The whole MS status word as received (the low byte describes the program area and is model-specific); null when
    /// the status was read with FINS, whose answer has no status word.
    /// </summary>
    public ushort? StatusWord { get; }

    /// <summary>
    /// Bit 7 of the status word: on CS/CJ, true when UM is not write-protected (W342 4-3-23); null when the status word
    /// was not reported (a FINS status read).
    /// </summary>
    public bool? UserMemoryWritable => StatusWord is { } word ? (word & 0x0080) != 0 : null;

    /// <summary>The 16-character FAL/FALS message when the PLC sent one, trailing spaces removed; otherwise null.</summary>
    public string? Message { get; }
}
