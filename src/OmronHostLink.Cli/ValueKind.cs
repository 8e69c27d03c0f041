namespace OmronHostLink.Cli;

/// <summary>Parsing of <c>--as</c>, with the console's usage error.</summary>
internal static class ValueKinds
{
    /// <summary>
    /// The types the console reads and writes: every <see cref="PlcValueType"/> but LREAL (double), which the library
    /// and the worker offer and the console's <c>--as</c> does not take.
    /// </summary>
    public static string[] Names => PlcValueTypes.Names.Where(n => n != PlcValueType.Double.Name()).ToArray();

    public static PlcValueType Parse(string text)
        => PlcValueTypes.TryParse(text, out PlcValueType type) && type != PlcValueType.Double
            ? type
            : throw new UsageException($"--as must be one of {string.Join(", ", Names)}; '{text}' is not.");
}
