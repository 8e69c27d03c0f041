namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// The two-character headers of Host Link commands and answers the library names in code. Their names in the manuals
/// and everything else about them are rows of <see cref="CModeCommandTable"/>; the area read and write headers
/// (RR … WE) belong to <see cref="CModeAreaInfo"/>.
/// </summary>
internal static class CModeHeaders
{
    /// <summary>MS: STATUS READ.</summary>
    public const string StatusRead = "MS";

    /// <summary>SC: STATUS CHANGE.</summary>
    public const string StatusChange = "SC";

    /// <summary>MF: ERROR READ.</summary>
    public const string ErrorRead = "MF";

    /// <summary>MM: PLC MODEL READ.</summary>
    public const string ModelRead = "MM";

    /// <summary>TS: TEST (the answer echoes the text, with no end code).</summary>
    public const string Test = "TS";

    /// <summary>KS: FORCED SET.</summary>
    public const string ForcedSet = "KS";

    /// <summary>KR: FORCED RESET.</summary>
    public const string ForcedReset = "KR";

    /// <summary>FK: MULTIPLE FORCED SET/RESET.</summary>
    public const string MultipleForcedSetReset = "FK";

    /// <summary>KC: FORCED SET/RESET CANCEL.</summary>
    public const string ForcedSetResetCancel = "KC";

    /// <summary>XZ: ABORT (no answer).</summary>
    public const string Abort = "XZ";

    /// <summary>FA: a FINS command or answer carried in a Host Link frame.</summary>
    public const string Fins = "FA";

    /// <summary>IC: the answer to a header the PLC does not know (no end code).</summary>
    public const string UndefinedCommand = "IC";

    /// <summary><c>**</c>: INITIALIZE (<c>@**</c>, no unit, no FCS, no answer).</summary>
    public const string Initialize = "**";

    /// <summary>EX: TXD sent by the PLC in Host Link mode (no end code).</summary>
    public const string Txd = "EX";

    /// <summary>The manuals' name of a header (<see cref="CModeCommandTable.Standard"/>), or null for a header they do not list.</summary>
    public static string? Name(string header) => CModeCommandTable.Standard.Name(Guard.NotNull(header));

    /// <summary>
    /// Whether this library executes the header on the PLC side: a row of <see cref="CModeCommandTable.Standard"/> it
    /// parses and executes, or FA (FINS). A PLC answers any other header with IC.
    /// </summary>
    public static bool IsExecutable(ReadOnlySpan<byte> header)
    {
        if (Is(header, Fins))
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
