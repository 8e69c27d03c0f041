using System.Buffers.Binary;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// FINS memory addresses read the PLC's way, for the rows' execution (<see cref="FinsCommandRow.Execute"/>): where an
/// element lies in a <see cref="IFinsPlc"/>'s memory, whether a range may be read or written, and the elements as the
/// answer and the write data carry them (words big-endian, bits and completion flags one byte each).
/// </summary>
/// <remarks>
/// Areas: CIO/W/H/A words (B0–B3) and bits (30–33), DM (82/02), timer/counter PVs (89; counter n at 0x8000 + n) and
/// completion flags (09), EM banks 0–C (A0–AC/20–2C) and the current bank (98/0A, always bank 0 here). Forced-status
/// areas, task flags and registers are answered 1101 (area missing). A0–A447 are read-only (2101).
/// </remarks>
internal static class FinsPlcMemory
{
    /// <summary>The response code for <paramref name="count"/> elements from <paramref name="address"/>: 0000 when they may be used.</summary>
    public static ushort Check(FinsMemoryAddress address, int count, bool write)
    {
        if (!IsSupported(address.AreaCode))
        {
            return FinsEndCodes.AreaClassificationMissing;
        }

        if (count == 0)
        {
            return FinsEndCodes.NormalCompletion;
        }

        if (!TryLocate(address, 0, out Location first) || !TryLocate(address, count - 1, out Location last)
            || first.Area != last.Area)
        {
            return FinsEndCodes.AddressRangeError;
        }

        if (write && first.Area == PlcArea.Auxiliary && first.Word < PlcAreaInfo.FirstWritableAuxiliaryWord)
        {
            return FinsEndCodes.WriteNotPossibleReadOnly;
        }

        return FinsEndCodes.NormalCompletion;
    }

    /// <summary>Where element <paramref name="index"/> from <paramref name="address"/> lies in the PLC's memory.</summary>
    public static bool TryLocate(FinsMemoryAddress address, int index, out Location location)
    {
        location = default;
        byte code = address.AreaCode;
        bool bitArea = FinsMemoryArea.IsBitArea(code);
        int word = address.Word;
        int bit = -1;
        if (bitArea && code != FinsMemoryArea.TimerCounterFlag)
        {
            int b = address.Bit + index;
            word += b / 16;
            bit = b % 16;
        }
        else
        {
            // The bit field of a word address is ignored: a published capture reads HR words with bit field 0D
            // and gets normal completion.
            word += index;
        }

        // The current EM bank is always bank 0.
        if (!FinsAddressing.TryLocate(code, word, currentEmBank: 0, out PlcArea area, out word, out int bank))
        {
            return false;
        }

        bool flag = code == FinsMemoryArea.TimerCounterFlag;
        if (flag && address.Bit != 0)
        {
            return false;
        }

        location = new Location(area, word, flag ? -1 : bit, bank, Flag: flag);
        return word < PlcAddress.AreaSize(area);
    }

    /// <summary>Reads <paramref name="count"/> elements (checked with <see cref="Check"/>) as the answer carries them.</summary>
    public static byte[] Read(IFinsPlc plc, FinsMemoryAddress address, int count)
    {
        int size = address.ElementSize;
        var bytes = new byte[count * size];
        for (int i = 0; i < count; i++)
        {
            TryLocate(address, i, out Location where);
            if (where.Flag)
            {
                bytes[i] = plc.GetFlag(where.Area, where.Word) ? (byte)1 : (byte)0;
            }
            else if (where.Bit >= 0)
            {
                bytes[i] = plc.GetBit(where.Area, where.Word, where.Bit, where.Bank) ? (byte)1 : (byte)0;
            }
            else
            {
                BinaryPrimitives.WriteUInt16BigEndian(bytes.AsSpan(i * 2), plc.ReadWord(where.Area, where.Word, where.Bank));
            }
        }

        return bytes;
    }

    /// <summary>Writes <paramref name="count"/> elements (checked with <see cref="Check"/>) from the write data.</summary>
    public static void Write(IFinsPlc plc, FinsMemoryAddress address, int count, ReadOnlySpan<byte> data)
    {
        for (int i = 0; i < count; i++)
        {
            TryLocate(address, i, out Location where);
            if (where.Flag || where.Bit >= 0)
            {
                Set(plc, where, data[i] != 0);
            }
            else
            {
                plc.WriteWord(where.Area, where.Word, BinaryPrimitives.ReadUInt16BigEndian(data.Slice(i * 2)), where.Bank);
            }
        }
    }

    /// <summary>Sets or clears one bit or completion flag.</summary>
    public static void Set(IFinsPlc plc, Location where, bool value)
    {
        if (where.Flag)
        {
            plc.SetFlag(where.Area, where.Word, value);
        }
        else
        {
            plc.SetBit(where.Area, where.Word, where.Bit, value, where.Bank);
        }
    }

    private static bool IsSupported(byte code) => FinsAddressing.TryLocate(code, 0, 0, out _, out _, out _);

    /// <summary>One element of PLC memory: a word, a bit of a word (<see cref="Bit"/> ≥ 0) or a completion flag.</summary>
    internal readonly record struct Location(PlcArea Area, int Word, int Bit, int Bank, bool Flag);
}
