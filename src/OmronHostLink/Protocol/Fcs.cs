namespace OmronHostLink.Protocol;

/// <summary>
/// The Host Link frame check sequence: the XOR of every character of a frame from its first character
/// (<c>@</c> in a first frame) to its last text character, sent as two upper-case hex characters.
/// </summary>
internal static class Fcs
{
    /// <summary>Computes the FCS over <paramref name="characters"/>.</summary>
    public static byte Compute(ReadOnlySpan<byte> characters)
    {
        int fcs = 0;
        foreach (byte c in characters)
        {
            fcs ^= c;
        }

        // Frames are 7-bit ASCII, so this never exceeds 0x7F; a byte with bit 7 set (line damage)
        // is deliberately not masked off, so that it changes the check instead of slipping through.
        return (byte)fcs;
    }

    /// <summary>Writes the FCS of <paramref name="characters"/> as two hex characters into <paramref name="destination"/>.</summary>
    public static void Write(ReadOnlySpan<byte> characters, Span<byte> destination) => HexAscii.WriteByte(Compute(characters), destination);

    /// <summary>
    /// Checks the two FCS characters <paramref name="found"/> against the FCS of <paramref name="characters"/>.
    /// </summary>
    /// <param name="characters">The checked characters.</param>
    /// <param name="found">The two FCS characters as received.</param>
    /// <param name="expected">The FCS the characters should have had.</param>
    public static bool Verify(ReadOnlySpan<byte> characters, ReadOnlySpan<byte> found, out byte expected)
    {
        // Exact characters: Omron writes the FCS in upper case, so "5e" for "5E" is a changed character, not a match.
        expected = Compute(characters);
        return found.Length == 2 && found[0] == HexAscii.Nibble(expected >> 4) && found[1] == HexAscii.Nibble(expected);
    }
}
