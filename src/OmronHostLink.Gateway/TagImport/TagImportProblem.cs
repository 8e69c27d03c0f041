namespace OmronHostLink.Gateway.TagImport;

/// <summary>A row of an import file that cannot be translated, and why.</summary>
/// <param name="Line">The line the row starts on (the header is line 1).</param>
/// <param name="Message">Why, in the file's terms.</param>
internal sealed record TagImportProblem(int Line, string Message)
{
    /// <summary><c>line N: why</c>.</summary>
    public override string ToString() => $"line {Line}: {Message}";
}
