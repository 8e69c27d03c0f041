namespace OmronHostLink.Cli;

/// <summary>Parsing of <c>--as</c>, with the console's usage error.</summary>
internal static class ValueKinds
{
    /// <summary>The types the console reads and writes: every <see cref="PlcValueType"/>.</summary>
    public static string[] Names => PlcValueTypes.Names.ToArray();

    public static PlcValueType Parse(string text)
        => PlcValueTypes.TryParse(text, out PlcValueType type)
            ? type
            : throw new UsageException($"--as must be one of {string.Join(", ", Names)}; '{text}' is not.");
}
