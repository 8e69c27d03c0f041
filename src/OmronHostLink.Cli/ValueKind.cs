namespace OmronHostLink.Cli;

/// <summary>Parsing of <c>--as</c>, with the console's usage error.</summary>
internal static class ValueKinds
{
    /// <summary>
    /// The types the console reads and writes: every <see cref="PlcValueType"/> but 8-digit BCD (bcd32), which the
    /// library and the worker offer and the console's <c>--as</c> does not take.
    /// </summary>
    public static string[] Names => PlcValueTypes.Names.Where(Offered).ToArray();

    public static PlcValueType Parse(string text)
        => PlcValueTypes.TryParse(text, out PlcValueType type) && Offered(type.Name())
            ? type
            : throw new UsageException($"--as must be one of {string.Join(", ", Names)}; '{text}' is not.");

    private static bool Offered(string name) => name != PlcValueType.Bcd32.Name();
}
