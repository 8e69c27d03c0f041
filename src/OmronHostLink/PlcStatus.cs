namespace OmronHostLink;

/// <summary>What MS (STATUS READ) reports: the operating mode, the status word, and any FAL/FALS message.</summary>
public sealed class PlcStatus
{
    /// <summary>Creates the status.</summary>
    public PlcStatus(PlcMode mode, ushort statusWord, string? message)
    {
        Mode = mode;
        StatusWord = statusWord;
        Message = message;
    }

    /// <summary>The operating mode (status bits 9-8: 00 PROGRAM, 10 RUN, 11 MONITOR).</summary>
    public PlcMode Mode { get; }

    /// <summary>The whole status word as received; the low byte describes the program area and is model-specific.</summary>
    public ushort StatusWord { get; }

    /// <summary>Bit 7 of the status word: on CS/CJ, 1 when UM is not write-protected (W342 4-3-23).</summary>
    public bool UserMemoryWritable => (StatusWord & 0x0080) != 0;

    /// <summary>The 16-character FAL/FALS message when the PLC sent one, trailing spaces removed; otherwise null.</summary>
    public string? Message { get; }
}
