namespace OmronHostLink;

/// <summary>How a 32-bit value is spread over two consecutive PLC words.</summary>
public enum WordOrder
{
    /// <summary>The word at the lower address holds the low 16 bits (Omron's own layout for DINT, UDINT, REAL and 8-digit BCD).</summary>
    LowWordFirst,

    /// <summary>The word at the lower address holds the high 16 bits (as some other vendors and programs store values).</summary>
    HighWordFirst,
}
