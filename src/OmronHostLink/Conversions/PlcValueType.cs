namespace OmronHostLink;

/// <summary>
/// How PLC words are read as values: the types <see cref="PlcValueCodec"/> decodes and encodes, shared by the console's
/// <c>--as</c>, the worker's poll groups and read tags.
/// </summary>
public enum PlcValueType
{
    /// <summary>One word, unsigned, shown as a raw word.</summary>
    Word,

    /// <summary>One word of 4 BCD digits (0-9999).</summary>
    Bcd,

    /// <summary>One word, signed.</summary>
    Int16,

    /// <summary>One word, unsigned.</summary>
    UInt16,

    /// <summary>Two words, signed, in the configured word order.</summary>
    Int32,

    /// <summary>Two words, unsigned, in the configured word order.</summary>
    UInt32,

    /// <summary>Two words, IEEE 754 single precision (REAL), in the configured word order.</summary>
    Float,

    /// <summary>ASCII text, two characters a word, high byte first.</summary>
    String,

    /// <summary>One bit of a word (or a timer/counter completion flag).</summary>
    Bit,

    /// <summary>Four words, IEEE 754 double precision (LREAL), in the configured word order.</summary>
    Double,

    /// <summary>Two words of 8 BCD digits (0-99999999), in the configured word order (Omron: the low four digits first).</summary>
    Bcd32,
}

/// <summary>Names and sizes of <see cref="PlcValueType"/>.</summary>
public static class PlcValueTypes
{
    private static readonly string[] NameList = ["word", "bcd", "int16", "uint16", "int32", "uint32", "float", "string", "bit", "double", "bcd32"];

    /// <summary>The names, lower case, in enum order, as users type them.</summary>
    public static IReadOnlyList<string> Names => NameList;

    /// <summary>Parses a name (case-insensitive, surrounding spaces ignored); numbers are refused.</summary>
    public static bool TryParse(string? text, out PlcValueType type)
    {
        int i = text is null ? -1 : Array.IndexOf(NameList, text.Trim().ToLowerInvariant());
        type = i < 0 ? default : (PlcValueType)i;
        return i >= 0;
    }

    /// <summary>The lower-case name.</summary>
    public static string Name(this PlcValueType type) => NameList[(int)type];

    /// <summary>Words one value occupies: 4 for Double, 2 for Int32, UInt32, Float and Bcd32, otherwise 1 (text and bits are not counted per value).</summary>
    public static int WordsPerValue(this PlcValueType type) => type switch
    {
        PlcValueType.Double => 4,
        PlcValueType.Int32 or PlcValueType.UInt32 or PlcValueType.Float or PlcValueType.Bcd32 => 2,
        _ => 1,
    };
}
