using System.Globalization;
using System.Text.Json;

namespace OmronHostLink.Cli;

/// <summary>What to read: an address, a number of values and how to present them.</summary>
internal sealed class ReadRequest
{
    /// <summary>Characters <c>--as string</c> reads when no count is given.</summary>
    public const int DefaultStringLength = 16;

    private ReadRequest(PlcAddress address, int count, PlcValueType kind, int words)
    {
        Address = address;
        Count = count;
        Kind = kind;
        Words = words;
    }

    public PlcAddress Address { get; }

    /// <summary>Values asked for (characters for string).</summary>
    public int Count { get; }

    public PlcValueType Kind { get; }

    /// <summary>Words read (0 for timer/counter completion flags, read one by one).</summary>
    public int Words { get; }

    public bool IsTimerCounterFlag => Kind == PlcValueType.Bit && Address.Area is PlcArea.Timer or PlcArea.Counter;

    /// <summary>Checks everything before anything is sent.</summary>
    public static ReadRequest Create(PlcAddress address, string? countText, string? kindText, HostLinkProtocol protocol)
    {
        PlcValueType kind = kindText is null
            ? address.IsBit ? PlcValueType.Bit : PlcValueType.Word
            : ValueKinds.Parse(kindText);
        bool timerCounter = address.Area is PlcArea.Timer or PlcArea.Counter;
        if (kind == PlcValueType.Bit && !address.IsBit && !timerCounter)
        {
            throw new UsageException($"{address} names a word; --as bit needs a bit address such as {address}.05.");
        }

        if (kind != PlcValueType.Bit && address.IsBit)
        {
            throw new UsageException($"{address} names a bit; read it with --as bit, or give the word address {address.AsWord()}.");
        }

        int maxCount = kind == PlcValueType.String ? 20000 : 10000;
        int count = countText is null
            ? kind == PlcValueType.String ? DefaultStringLength : 1
            : (int)Numbers.ParseInteger(countText, 1, maxCount, "The count");

        int words;
        if (kind == PlcValueType.Bit)
        {
            if (timerCounter)
            {
                Addresses.EnsureRange(address, count, protocol, forWrite: false);
                return new ReadRequest(address, count, kind, 0);
            }

            words = (address.Bit + count + 15) / 16;
            Addresses.EnsureRange(address.AsWord(), words, protocol, forWrite: false);
        }
        else
        {
            words = kind == PlcValueType.String ? PlcWords.WordsForString(count) : count * kind.WordsPerValue();
            Addresses.EnsureRange(address, words, protocol, forWrite: false);
        }

        return new ReadRequest(address, count, kind, words);
    }

    /// <summary>Reads the values: one command for any number of words (the answer spans frames as needed).</summary>
    public async Task<Snapshot> ReadAsync(HostLinkUnit plc, CancellationToken cancellationToken)
    {
        if (IsTimerCounterFlag)
        {
            var flags = new bool[Count];
            for (int i = 0; i < Count; i++)
            {
                flags[i] = await plc.ReadBitAsync(PlcAddress.WordOf(Address.Area, Address.Word + i), cancellationToken).ConfigureAwait(false);
            }

            return new Snapshot(this, [], flags);
        }

        ushort[] words = await plc.ReadWordsAsync(Address.AsWord(), Words, cancellationToken).ConfigureAwait(false);
        if (Kind != PlcValueType.Bit)
        {
            return new Snapshot(this, words, null);
        }

        var bits = new bool[Count];
        for (int i = 0; i < Count; i++)
        {
            int n = Address.Bit + i;
            bits[i] = PlcWords.GetBit(words[n / 16], n % 16);
        }

        return new Snapshot(this, words, bits);
    }
}

/// <summary>Values read at one moment, with their presentation.</summary>
internal sealed class Snapshot
{
    public Snapshot(ReadRequest request, ushort[] words, bool[]? bits)
    {
        Request = request;
        Words = words;
        Bits = bits;
    }

    public ReadRequest Request { get; }

    public ushort[] Words { get; }

    public bool[]? Bits { get; }

    private PlcValueType Kind => Request.Kind;

    public int ValueCount => Kind switch
    {
        PlcValueType.Bit => Bits!.Length,
        PlcValueType.String => 1,
        _ => Request.Count,
    };

    /// <summary>The address of value <paramref name="i"/>.</summary>
    public PlcAddress AddressOf(int i)
    {
        PlcAddress a = Request.Address;
        if (Kind == PlcValueType.Bit)
        {
            if (Request.IsTimerCounterFlag)
            {
                return PlcAddress.WordOf(a.Area, a.Word + i);
            }

            int n = a.Bit + i;
            return a.AsWord().Offset(n / 16).WithBit(n % 16);
        }

        return Kind == PlcValueType.String ? a : a.Offset(i * Kind.WordsPerValue());
    }

    /// <summary>Whether value <paramref name="i"/> differs from the same value in <paramref name="other"/>.</summary>
    public bool Differs(Snapshot? other, int i)
    {
        if (other is null)
        {
            return true;
        }

        if (Kind == PlcValueType.Bit)
        {
            return Bits![i] != other.Bits![i];
        }

        if (Kind == PlcValueType.String)
        {
            return !Words.AsSpan().SequenceEqual(other.Words);
        }

        int per = Kind.WordsPerValue();
        return !Words.AsSpan(i * per, per).SequenceEqual(other.Words.AsSpan(i * per, per));
    }

    /// <summary>The value in words for people, with hex and decimal where both say something.</summary>
    public string Human(int i)
    {
        switch (Kind)
        {
            case PlcValueType.Bit:
                return Bits![i] ? "1 (ON)" : "0 (OFF)";
            case PlcValueType.String:
                return "\"" + Protocol.FrameText.Printable(TextBytes()) + "\"";
            case PlcValueType.Int32:
            case PlcValueType.UInt32:
            case PlcValueType.Float:
                uint raw = PlcWords.ReadUInt32(Words.AsSpan(i * 2, 2));
                string v = Kind switch
                {
                    PlcValueType.Int32 => Numbers.Invariant(PlcWords.ReadInt32(Words.AsSpan(i * 2, 2))),
                    PlcValueType.UInt32 => Numbers.Invariant(raw),
                    _ => PlcWords.ReadSingle(Words.AsSpan(i * 2, 2)).ToString("R", CultureInfo.InvariantCulture),
                };
                return $"{v}  ({Numbers.Hex(raw)})";
            default:
                ushort w = Words[i];
                return Kind switch
                {
                    PlcValueType.Int16 => $"{Numbers.Invariant(PlcWords.ToInt16(w))}  ({Numbers.Hex(w)})",
                    PlcValueType.Bcd => TryBcd(w, out int bcd) ? $"{Numbers.Invariant(bcd)}  (BCD {Numbers.Hex(w)})" : $"not BCD  ({Numbers.Hex(w)})",
                    _ => $"{Numbers.Hex(w)}  {Numbers.Invariant(w)}",
                };
        }
    }

    /// <summary>The value in its natural JSON type (words as unsigned integers; a word that is not BCD as null; NaN/∞ as null).</summary>
    public void WriteJson(Utf8JsonWriter json, int i)
    {
        switch (Kind)
        {
            case PlcValueType.Bit:
                json.WriteBooleanValue(Bits![i]);
                break;
            case PlcValueType.String:
                json.WriteStringValue(Text());
                break;
            case PlcValueType.Int32:
                json.WriteNumberValue(PlcWords.ReadInt32(Words.AsSpan(i * 2, 2)));
                break;
            case PlcValueType.UInt32:
                json.WriteNumberValue(PlcWords.ReadUInt32(Words.AsSpan(i * 2, 2)));
                break;
            case PlcValueType.Float:
                float f = PlcWords.ReadSingle(Words.AsSpan(i * 2, 2));
                if (float.IsFinite(f))
                {
                    json.WriteNumberValue(f);
                }
                else
                {
                    json.WriteNullValue();
                }

                break;
            case PlcValueType.Int16:
                json.WriteNumberValue(PlcWords.ToInt16(Words[i]));
                break;
            case PlcValueType.Bcd:
                if (TryBcd(Words[i], out int bcd))
                {
                    json.WriteNumberValue(bcd);
                }
                else
                {
                    json.WriteNullValue();
                }

                break;
            default:
                json.WriteNumberValue(Words[i]);
                break;
        }
    }

    /// <summary>The common fields of a read result.</summary>
    public void WriteJsonFields(Utf8JsonWriter json, IEnumerable<int>? indexes = null)
    {
        json.WriteString("address", Request.Address.ToString());
        json.WriteNumber("count", Request.Count);
        json.WriteString("as", Kind.Name());
        json.WriteStartArray("values");
        for (int i = 0; i < ValueCount; i++)
        {
            WriteJson(json, i);
        }

        json.WriteEndArray();
        if (indexes is not null)
        {
            json.WriteStartArray("changed");
            foreach (int i in indexes)
            {
                json.WriteStringValue(AddressOf(i).ToString());
            }

            json.WriteEndArray();
        }
    }

    /// <summary>The characters of a string read: two a word, high byte first, up to the first NUL or the count.</summary>
    private byte[] TextBytes()
    {
        var bytes = new List<byte>(Request.Count);
        for (int n = 0; n < Request.Count && n / 2 < Words.Length; n++)
        {
            ushort w = Words[n / 2];
            byte b = (byte)(n % 2 == 0 ? w >> 8 : w & 0xFF);
            if (b == 0)
            {
                break;
            }

            bytes.Add(b);
        }

        return bytes.ToArray();
    }

    private string Text() => System.Text.Encoding.Latin1.GetString(TextBytes());

    private static bool TryBcd(ushort word, out int value)
    {
        try
        {
            value = PlcWords.FromBcd(word);
            return true;
        }
        catch (FormatException)
        {
            value = 0;
            return false;
        }
    }
}
