namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// A FINS memory address: area code (1 byte), word address (2 bytes) and bit (1 byte), as commands 0101–0105 and
/// 2301 carry it.
/// </summary>
internal readonly struct FinsMemoryAddress : IEquatable<FinsMemoryAddress>
{
    /// <summary>Bytes the address takes in a command: area, word, bit.</summary>
    public const int Length = 4;

    /// <summary>Creates an address.</summary>
    /// <param name="areaCode">A FINS area code (see <see cref="FinsMemoryArea"/>).</param>
    /// <param name="word">The word address, 0–65535 (timer <c>n</c> = <c>n</c>, counter <c>n</c> = 0x8000 + <c>n</c>).</param>
    /// <param name="bit">The bit, 0–15, for a bit area; must be 0 for any other area.</param>
    /// <exception cref="ArgumentException">The area code is not a known CS/CJ code.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The word or bit is out of range.</exception>
    public FinsMemoryAddress(byte areaCode, int word, int bit = 0)
    {
        if (!FinsMemoryArea.IsDefined(areaCode))
        {
            throw new ArgumentException($"{areaCode:X2} is not a CS/CJ FINS memory area code.", nameof(areaCode));
        }

        Guard.InRange(word, 0, ushort.MaxValue);
        if (FinsMemoryArea.IsBitArea(areaCode))
        {
            Guard.InRange(bit, 0, 15);
        }
        else if (bit != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(bit), bit, $"Area {areaCode:X2} ({FinsMemoryArea.Describe(areaCode)}) is not bit-addressed; the bit must be 0.");
        }

        AreaCode = areaCode;
        Word = (ushort)word;
        Bit = (byte)bit;
    }

    // Parsing path: no check of the bit against the area (see Read).
    private FinsMemoryAddress(byte areaCode, ushort word, byte bit, bool unchecked_)
    {
        _ = unchecked_;
        AreaCode = areaCode;
        Word = word;
        Bit = bit;
    }

    /// <summary>The FINS area code.</summary>
    public byte AreaCode { get; }

    /// <summary>The word address.</summary>
    public ushort Word { get; }

    /// <summary>The bit (0 for word areas).</summary>
    public byte Bit { get; }

    /// <summary>Whether the area code addresses bits.</summary>
    public bool IsBit => FinsMemoryArea.IsBitArea(AreaCode);

    /// <summary>Bytes one element at this address takes in read or write data.</summary>
    public int ElementSize => FinsMemoryArea.ElementSize(AreaCode);

    /// <summary>Writes area, word and bit (4 bytes).</summary>
    public void Write(Span<byte> destination)
    {
        destination[0] = AreaCode;
        destination[1] = (byte)(Word >> 8);
        destination[2] = (byte)Word;
        destination[3] = Bit;
    }

    /// <summary>
    /// Reads area, word and bit from 4 bytes of a command. Unlike the constructor, a non-zero bit field with a word
    /// area is kept as received (a published frame reads HR words with bit field 0D), so that the command re-encodes
    /// byte for byte; a simulator can refuse it by checking <see cref="Bit"/> against <see cref="IsBit"/>.
    /// </summary>
    /// <exception cref="FinsFormatException">1101 for an unknown area code, 1103 for a bit above 15.</exception>
    public static FinsMemoryAddress Read(ReadOnlySpan<byte> source)
    {
        byte area = source[0];
        int word = (source[1] << 8) | source[2];
        byte bit = source[3];
        if (!FinsMemoryArea.IsDefined(area))
        {
            throw new FinsFormatException(FinsEndCodes.AreaClassificationMissing, $"Area code {area:X2} is not a CS/CJ memory area.");
        }

        if (bit > 15)
        {
            throw new FinsFormatException(FinsEndCodes.AddressRangeError, $"Bit {bit:X2} is out of range (00-0F) for area {area:X2} ({FinsMemoryArea.Describe(area)}).");
        }

        return new FinsMemoryAddress(area, (ushort)word, bit, unchecked_: true);
    }

    /// <inheritdoc/>
    public bool Equals(FinsMemoryAddress other) => AreaCode == other.AreaCode && Word == other.Word && Bit == other.Bit;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is FinsMemoryAddress other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => (AreaCode << 24) | (Word << 8) | Bit;

    /// <summary>The address as area code, word and bit in hex (for example <c>82:01F4.00</c>).</summary>
    public override string ToString() => $"{AreaCode:X2}:{Word:X4}.{Bit:X2}";

    /// <summary>Equality.</summary>
    public static bool operator ==(FinsMemoryAddress left, FinsMemoryAddress right) => left.Equals(right);

    /// <summary>Inequality.</summary>
    public static bool operator !=(FinsMemoryAddress left, FinsMemoryAddress right) => !left.Equals(right);
}
