namespace OmronHostLink.Cli;

/// <summary>Parsing of <c>--as</c>, with the console's usage error.</summary>
internal static class ValueKinds
{
    /// <summary>CX-Programmer's names of the floating-point types, taken for the library's: REAL is float, LREAL double.</summary>
    private static readonly Dictionary<string, PlcValueType> Aliases = new(StringComparer.OrdinalIgnoreCase)
    {
        ["real"] = PlcValueType.Float,
        ["lreal"] = PlcValueType.Double,
    };

    /// <summary>
    /// The types the console reads and writes: every <see cref="PlcValueType"/> but 8-digit BCD (bcd32), which the
    /// library and the worker offer and the console's <c>--as</c> does not take.
    /// </summary>
    public static string[] Names => PlcValueTypes.Names.Where(Offered).ToArray();

    /// <summary>The words <c>--as</c> takes: <see cref="Names"/> and CX-Programmer's <c>real</c> and <c>lreal</c>.</summary>
    public static string[] Accepted => [.. Names, .. Aliases.Keys];

    public static PlcValueType Parse(string text)
        => Aliases.TryGetValue(text.Trim(), out PlcValueType alias) ? alias
            : PlcValueTypes.TryParse(text, out PlcValueType type) && Offered(type.Name())
            ? type
            : throw new UsageException($"--as must be one of {string.Join(", ", Accepted)}; '{text}' is not.");

    private static bool Offered(string name) => name != PlcValueType.Bcd32.Name();
}
