namespace OmronHostLink.Cli;

/// <summary>How words are read and written (<c>--as</c>).</summary>
internal enum ValueKind
{
    Word,
    Bcd,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Float,
    String,
    Bit,
}

internal static class ValueKinds
{
    public static readonly string[] Names = ["word", "bcd", "int16", "uint16", "int32", "uint32", "float", "string", "bit"];

    public static ValueKind Parse(string text) => text.ToLowerInvariant() switch
    {
        "word" => ValueKind.Word,
        "bcd" => ValueKind.Bcd,
        "int16" => ValueKind.Int16,
        "uint16" => ValueKind.UInt16,
        "int32" => ValueKind.Int32,
        "uint32" => ValueKind.UInt32,
        "float" => ValueKind.Float,
        "string" => ValueKind.String,
        "bit" => ValueKind.Bit,
        _ => throw new UsageException($"--as must be one of {string.Join(", ", Names)}; '{text}' is not."),
    };

    public static string Name(this ValueKind kind) => Names[(int)kind];

    /// <summary>Words one value occupies (string: not per value; bit: not word-based).</summary>
    public static int WordsPerValue(this ValueKind kind) => kind is ValueKind.Int32 or ValueKind.UInt32 or ValueKind.Float ? 2 : 1;
}
