namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// The two-character headers of Host Link commands and answers, with their names in the manuals (W342 section 4;
/// C200HX). The area read and write headers (RR … WE) belong to <see cref="CModeAreaInfo"/>.
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

    private static readonly string[] ExecutableHeaders =
    [
        StatusRead, StatusChange, ErrorRead, ModelRead, Test, ForcedSet, ForcedReset, MultipleForcedSetReset, ForcedSetResetCancel, Abort, Fins,
    ];

    private static readonly Dictionary<string, string> Names = new(StringComparer.Ordinal)
    {
        ["RR"] = "CIO AREA READ",
        ["RL"] = "LR AREA READ",
        ["RH"] = "HR AREA READ",
        ["RC"] = "TIMER/COUNTER PV READ",
        ["RG"] = "TIMER/COUNTER STATUS READ",
        ["RD"] = "DM AREA READ",
        ["RJ"] = "AR AREA READ",
        ["RE"] = "EM AREA READ",
        ["WR"] = "CIO AREA WRITE",
        ["WL"] = "LR AREA WRITE",
        ["WH"] = "HR AREA WRITE",
        ["WC"] = "TIMER/COUNTER PV WRITE",
        ["WG"] = "TIMER/COUNTER STATUS WRITE",
        ["WD"] = "DM AREA WRITE",
        ["WJ"] = "AR AREA WRITE",
        ["WE"] = "EM AREA WRITE",
        ["R#"] = "SV READ 1",
        ["R$"] = "SV READ 2",
        ["R%"] = "SV READ 3",
        ["W#"] = "SV CHANGE 1",
        ["W$"] = "SV CHANGE 2",
        ["W%"] = "SV CHANGE 3",
        [StatusRead] = "STATUS READ",
        [StatusChange] = "STATUS CHANGE",
        [ErrorRead] = "ERROR READ",
        [ForcedSet] = "FORCED SET",
        [ForcedReset] = "FORCED RESET",
        [MultipleForcedSetReset] = "MULTIPLE FORCED SET/RESET",
        [ForcedSetResetCancel] = "FORCED SET/RESET CANCEL",
        [ModelRead] = "PLC MODEL READ",
        [Test] = "TEST",
        ["RP"] = "PROGRAM READ",
        ["WP"] = "PROGRAM WRITE",
        ["MI"] = "I/O TABLE GENERATE",
        ["QQ"] = "COMPOUND COMMAND (QQMR/QQIR)",
        [Abort] = "ABORT",
        [Initialize] = "INITIALIZE",
        [UndefinedCommand] = "UNDEFINED COMMAND (response)",
        [Txd] = "TXD (PLC to host)",
        [Fins] = "FINS COMMAND OVER HOST LINK",
    };

    /// <summary>The manuals' name of a header, or null for a header they do not list.</summary>
    public static string? Name(string header) => Names.TryGetValue(Guard.NotNull(header), out string? name) ? name : null;

    /// <summary>
    /// Whether this library executes the header on the PLC side: every area read and write
    /// (<see cref="CModeAreaInfo.TryFromHeader"/>), MS, SC, MF, MM, TS, KS, KR, FK, KC, XZ (<see cref="CModeCommand.Parse"/>)
    /// and FA. A PLC answers any other header with IC.
    /// </summary>
    public static bool IsExecutable(ReadOnlySpan<byte> header)
    {
        if (CModeAreaInfo.TryFromHeader(header, out _, out _))
        {
            return true;
        }

        foreach (string executable in ExecutableHeaders)
        {
            if (Is(header, executable))
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
