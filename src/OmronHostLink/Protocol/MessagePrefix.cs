namespace OmronHostLink.Protocol;

/// <summary>
/// The start every Host Link message shares, commands and answers, C-mode and FINS alike: <c>@</c>, the unit number as
/// two decimal digits, and the two header characters (<c>@00RD</c>, <c>@31FA</c>).
/// </summary>
internal static class MessagePrefix
{
    /// <summary>Characters of <c>@</c> and the unit number.</summary>
    public const int UnitLength = 3;

    /// <summary>Characters of <c>@</c>, the unit number and the header.</summary>
    public const int Length = 5;

    /// <summary>Writes <c>@</c> and the unit number as two digits.</summary>
    /// <returns><see cref="UnitLength"/>.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The unit is not 0-31.</exception>
    public static int WriteUnit(Span<byte> destination, int unit)
    {
        Guard.Unit(unit);
        destination[0] = (byte)'@';
        HexAscii.WriteDecimal(unit, destination.Slice(1, 2));
        return UnitLength;
    }

    /// <summary>Writes <c>@</c>, the unit number and the two-character <paramref name="header"/>.</summary>
    /// <returns><see cref="Length"/>.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The unit is not 0-31.</exception>
    public static int Write(Span<byte> destination, int unit, string header)
    {
        WriteUnit(destination, unit);
        destination[3] = (byte)header[0];
        destination[4] = (byte)header[1];
        return Length;
    }

    /// <summary>Reads the unit number of a message or first frame: <c>@</c> and two decimal digits (00-99).</summary>
    /// <returns>False when the text does not start that way.</returns>
    public static bool TryReadUnit(ReadOnlySpan<byte> message, out int unit)
    {
        unit = -1;
        return message.Length >= UnitLength && message[0] == (byte)'@' && HexAscii.TryParseDecimal(message.Slice(1, 2), out unit);
    }
}
