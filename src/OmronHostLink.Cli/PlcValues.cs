using System.Text;
using System.Text.Json;

namespace OmronHostLink.Cli;

/// <summary>What to read: an address, a number of values and how to present them.</summary>
internal sealed class ReadRequest
{
    /// <summary>Characters <c>--as string</c> reads when no count is given.</summary>
    public const int DefaultStringLength = 16;

    private ReadRequest(PlcAddress address, int count, PlcValueType kind, int words, WordOrder order)
    {
        Address = address;
        Count = count;
        Kind = kind;
        Words = words;
        Order = order;
    }

    public PlcAddress Address { get; }

    /// <summary>Values asked for (characters for string).</summary>
    public int Count { get; }

    public PlcValueType Kind { get; }

    /// <summary>Words read (0 for timer/counter completion flags, read one by one).</summary>
    public int Words { get; }

    /// <summary>How 32- and 64-bit values lie in their words.</summary>
    public WordOrder Order { get; }

    public bool IsTimerCounterFlag => Kind == PlcValueType.Bit && Address.Area is PlcArea.Timer or PlcArea.Counter;

    /// <summary>Checks everything before anything is sent.</summary>
    public static ReadRequest Create(PlcAddress address, string? countText, string? kindText, HostLinkCommandSet protocol, WordOrder order)
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
                return new ReadRequest(address, count, kind, 0, order);
            }

            words = PlcValueCodec.WordCount(kind, count, address.Bit);
            Addresses.EnsureRange(address.AsWord(), words, protocol, forWrite: false);
        }
        else
        {
            words = PlcValueCodec.WordCount(kind, count);
            Addresses.EnsureRange(address, words, protocol, forWrite: false);
        }

        return new ReadRequest(address, count, kind, words, order);
    }

    /// <summary>Reads the values: one command for any number of words (the answer spans frames as needed).</summary>
    public async Task<Snapshot> ReadAsync(HostLinkUnit plc, CancellationToken cancellationToken)
    {
        if (IsTimerCounterFlag)
        {
            var flags = new PlcValue?[Count];
            for (int i = 0; i < Count; i++)
            {
                flags[i] = PlcValue.FromBit(await plc.ReadBitAsync(PlcAddress.WordOf(Address.Area, Address.Word + i), cancellationToken).ConfigureAwait(false));
            }

            return new Snapshot(this, [], flags);
        }

        ushort[] words = await plc.ReadWordsAsync(Address.AsWord(), Words, cancellationToken).ConfigureAwait(false);
        return new Snapshot(this, words, Decode(words));
    }

    /// <summary>The values in the words; null where the words hold no value of the type (not BCD, not ASCII text).</summary>
    public PlcValue?[] Decode(ushort[] words)
    {
        if (Kind == PlcValueType.String)
        {
            try
            {
                return [PlcValueCodec.DecodeValues(Kind, words, Count, Order)[0]];
            }
            catch (FormatException)
            {
                return [null];
            }
        }

        var values = new PlcValue?[Count];
        int per = Kind.WordsPerValue();
        for (int i = 0; i < values.Length; i++)
        {
            bool bit = Kind == PlcValueType.Bit;
            values[i] = PlcValueCodec.TryDecode(Kind, bit ? words : words.AsSpan(i * per, per), Order, bit ? Address.Bit + i : 0, out PlcValue value)
                ? value
                : null;
        }

        return values;
    }
}

/// <summary>Values read at one moment, with their presentation.</summary>
internal sealed class Snapshot
{
    public Snapshot(ReadRequest request, ushort[] words, PlcValue?[] values)
    {
        Request = request;
        Words = words;
        Values = values;
    }

    public ReadRequest Request { get; }

    public ushort[] Words { get; }

    /// <summary>The decoded values; null where the words hold no value of the type.</summary>
    public PlcValue?[] Values { get; }

    private PlcValueType Kind => Request.Kind;

    public int ValueCount => Values.Length;

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

    /// <summary>The value in words for people, with hex and decimal where both say something.</summary>
    public string Human(int i)
    {
        PlcValue? value = Values[i];
        switch (Kind)
        {
            case PlcValueType.Bit:
                return value!.Value.ToBoolean() ? "1 (ON)" : "0 (OFF)";
            case PlcValueType.String:
                return value is { } text
                    ? "\"" + Protocol.FrameText.Printable(Encoding.ASCII.GetBytes(text.ToString())) + "\""
                    : $"not ASCII text  ({string.Join(" ", Words.Select(Numbers.Hex))})";
            case PlcValueType.Int32:
            case PlcValueType.UInt32:
            case PlcValueType.Float:
                return $"{value}  ({Numbers.Hex(PlcWords.ReadUInt32(Words.AsSpan(i * 2, 2), Request.Order))})";
            case PlcValueType.Double:
                return $"{value}  (0x{BitConverter.DoubleToInt64Bits(value!.Value.ToDouble()):X16})";
            default:
                ushort w = Words[i];
                return Kind switch
                {
                    PlcValueType.Int16 => $"{value}  ({Numbers.Hex(w)})",
                    PlcValueType.Bcd => value is { } bcd ? $"{bcd}  (BCD {Numbers.Hex(w)})" : $"not BCD  ({Numbers.Hex(w)})",
                    _ => $"{Numbers.Hex(w)}  {Numbers.Invariant(w)}",
                };
        }
    }

    /// <summary>The value in its natural JSON type (words as unsigned integers; words that hold no value of the type as null; NaN/∞ as null).</summary>
    public void WriteJson(Utf8JsonWriter json, int i)
    {
        if (Values[i] is not { } value)
        {
            json.WriteNullValue();
            return;
        }

        switch (value.Type)
        {
            case PlcValueType.Bit:
                json.WriteBooleanValue(value.ToBoolean());
                break;
            case PlcValueType.String:
                json.WriteStringValue(value.ToString());
                break;
            case PlcValueType.Int32 or PlcValueType.Bcd:
                json.WriteNumberValue(value.ToInt32());
                break;
            case PlcValueType.UInt32:
                json.WriteNumberValue(value.ToUInt32());
                break;
            case PlcValueType.Int16:
                json.WriteNumberValue(value.ToInt16());
                break;
            case PlcValueType.Float when float.IsFinite(value.ToSingle()):
                json.WriteNumberValue(value.ToSingle());
                break;
            case PlcValueType.Double when double.IsFinite(value.ToDouble()):
                json.WriteNumberValue(value.ToDouble());
                break;
            case PlcValueType.Float or PlcValueType.Double:
                json.WriteNullValue();
                break;
            default:
                json.WriteNumberValue(value.ToUInt16());
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
}
