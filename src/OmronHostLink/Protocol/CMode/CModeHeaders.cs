namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// What the rows do not say about headers: how two header characters are compared, and which headers a PLC of this
/// library executes (the rows of <see cref="CModeCommandTable.Standard"/> that it parses and executes, and FA). Every
/// header itself, its name and everything else about it is a row (<see cref="CModeCommands"/>, the command types' own
/// rows); code that needs a particular header names its row (<c>CModeCommands.Test.Header</c>).
/// </summary>
internal static class CModeHeaders
{
    /// <summary>The manuals' name of a header (<see cref="CModeCommandTable.Standard"/>), or null for a header they do not list.</summary>
    public static string? Name(string header) => CModeCommandTable.Standard.Name(Guard.NotNull(header));

    /// <summary>
    /// Whether this library executes the header on the PLC side: a row of <see cref="CModeCommandTable.Standard"/> it
    /// parses and executes, or FA (FINS). A PLC answers any other header with IC.
    /// </summary>
    public static bool IsExecutable(ReadOnlySpan<byte> header)
    {
        if (Is(header, CModeCommands.Fins.Header))
        {
            return true;
        }

        foreach (CModeCommandRow row in CModeCommandTable.Standard.Rows)
        {
            if (row.IsExecutable && Is(header, row.Header))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Whether <paramref name="header"/> holds the two characters of <paramref name="expected"/>.</summary>
    public static bool Is(ReadOnlySpan<byte> header, string expected)
        => header.Length == 2 && header[0] == (byte)expected[0] && header[1] == (byte)expected[1];
}
