namespace OmronHostLink;

/// <summary>How a PLC model holds timer and counter present values.</summary>
public enum TimerCounterCoding
{
    /// <summary>Always four BCD digits (0000–9999).</summary>
    Bcd,

    /// <summary>BCD by default, binary when the PLC's properties say so (a CX-Programmer setting): the reader must know which.</summary>
    BcdOrBinary,
}
