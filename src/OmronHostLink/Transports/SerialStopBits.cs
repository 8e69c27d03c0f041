namespace OmronHostLink.Transports;

/// <summary>Number of stop bits after each character on a serial line.</summary>
public enum SerialStopBits
{
    /// <summary>One stop bit.</summary>
    One = 1,

    /// <summary>Two stop bits (the Omron Host Link default).</summary>
    Two = 2,
}
