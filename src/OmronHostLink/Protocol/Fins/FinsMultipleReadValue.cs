namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// One item of a 0104 MULTIPLE MEMORY AREA READ response: the area code echoed and the element's value
/// (1 byte for a bit, 2 for a word, 4 for a word with forced status or an index register).
/// </summary>
internal readonly struct FinsMultipleReadValue : IEquatable<FinsMultipleReadValue>
{
    /// <summary>Creates an item.</summary>
    /// <param name="areaCode">The area code (decides the element size).</param>
    /// <param name="value">The element's value; must fit in the element size.</param>
    /// <exception cref="ArgumentException">Unknown area code, or a value too large for its element.</exception>
    public FinsMultipleReadValue(byte areaCode, uint value)
    {
        int size = FinsMemoryArea.ElementSize(areaCode);
        if (size == 0)
        {
            throw new ArgumentException($"{areaCode:X2} is not a CS/CJ FINS memory area code.", nameof(areaCode));
        }

        if (size < 4 && value >> (size * 8) != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, $"A {FinsMemoryArea.Describe(areaCode)} element holds {size} byte(s).");
        }

        AreaCode = areaCode;
        Value = value;
    }

    /// <summary>The area code the PLC echoed.</summary>
    public byte AreaCode { get; }

    /// <summary>The element's value (a bit is 0 or 1).</summary>
    public uint Value { get; }

    /// <summary>Bytes of the element.</summary>
    public int Size => FinsMemoryArea.ElementSize(AreaCode);

    /// <summary>The value as a word (the low 16 bits).</summary>
    public ushort Word => (ushort)Value;

    /// <summary>The value as a bit (non-zero = ON).</summary>
    public bool Bit => Value != 0;

    /// <summary>
    /// Decodes the response data of <paramref name="command"/>: per item, the area code (which must echo the
    /// command's) and the element.
    /// </summary>
    /// <exception cref="HostLinkFrameException">
    /// <see cref="FrameError.WrongLength"/> when the data is not exactly the expected length;
    /// <see cref="FrameError.WrongHeader"/> when an area code does not echo the command's.
    /// </exception>
    public static FinsMultipleReadValue[] ReadAll(ReadOnlySpan<byte> data, MultipleMemoryAreaReadCommand command)
    {
        Guard.NotNull(command);
        if (data.Length != command.ResponseDataLength)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"The MULTIPLE MEMORY AREA READ response carries {data.Length} data bytes; {command.Items.Count} items need exactly {command.ResponseDataLength}.");
        }

        var values = new FinsMultipleReadValue[command.Items.Count];
        int at = 0;
        for (int i = 0; i < values.Length; i++)
        {
            FinsMemoryAddress item = command.Items[i];
            if (data[at] != item.AreaCode)
            {
                throw new HostLinkFrameException(FrameError.WrongHeader, $"Item {i} of the MULTIPLE MEMORY AREA READ response has area code {data[at]:X2}; the command asked for {item.AreaCode:X2}.");
            }

            uint value = 0;
            for (int b = 0; b < item.ElementSize; b++)
            {
                value = (value << 8) | data[at + 1 + b];
            }

            values[i] = new FinsMultipleReadValue(item.AreaCode, value);
            at += 1 + item.ElementSize;
        }

        return values;
    }

    /// <summary>Encodes response items (area code + element each) into <paramref name="destination"/>.</summary>
    /// <returns>The number of bytes written.</returns>
    public static int WriteAll(ReadOnlySpan<FinsMultipleReadValue> values, Span<byte> destination)
    {
        int at = 0;
        foreach (FinsMultipleReadValue v in values)
        {
            int size = v.Size;
            if (size == 0 || destination.Length < at + 1 + size)
            {
                throw new ArgumentException("The destination is too small, or an item is not initialised.", nameof(destination));
            }

            destination[at] = v.AreaCode;
            for (int b = 0; b < size; b++)
            {
                destination[at + 1 + b] = (byte)(v.Value >> ((size - 1 - b) * 8));
            }

            at += 1 + size;
        }

        return at;
    }

    /// <inheritdoc/>
    public bool Equals(FinsMultipleReadValue other) => AreaCode == other.AreaCode && Value == other.Value;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is FinsMultipleReadValue other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => (AreaCode * 397) ^ (int)Value;

    /// <summary>Area code and value in hex.</summary>
    public override string ToString() => $"{AreaCode:X2}:{Value:X}";

    /// <summary>Equality.</summary>
    public static bool operator ==(FinsMultipleReadValue left, FinsMultipleReadValue right) => left.Equals(right);

    /// <summary>Inequality.</summary>
    public static bool operator !=(FinsMultipleReadValue left, FinsMultipleReadValue right) => !left.Equals(right);
}
