namespace OmronHostLink.Transports;

/// <summary>Parity bit of each character on a serial line.</summary>
public enum SerialParity
{
    /// <summary>No parity bit.</summary>
    None,

    /// <summary>Even parity (the Omron Host Link default).</summary>
    Even,

    /// <summary>Odd parity.</summary>
    Odd,
}
