namespace OmronHostLink.Testing;

/// <summary>
/// QQ frames written by hand from the command and response formats of the manuals (the FCS computed separately, not
/// with this library): W342 4-3-35 REGISTER I/O MEMORY – QQMR and 4-3-36 READ I/O MEMORY – QQIR (p146–147 of the
/// 07-2009 edition; end codes p105: QQMR 00 13 14 15 18 21 A3–A8, QQIR 00 13 14 18 19); C200HS operation manual 11-3-33
/// COMPOUND COMMAND – QQ (p428–429); CPM1 programming manual 4-5-30 (p302); CQM1H programming manual 6-5-34 (p470–471).
/// Item: read area (4 characters, spaces filled: <c>CIO </c>, <c>DM  </c>, <c>TIM </c>), word (4 decimal digits), data
/// format (bit <c>00</c>–<c>15</c> or <c>CH</c>), items separated by <c>,</c>. QQIR answer: the items in registration
/// order, separated by <c>,</c>: a bit as 0/1, a word as four hex digits, a timer/counter PV as its Completion Flag followed
/// by the PV. The manuals show formats only; these frames instantiate them.
/// </summary>
public static class CompoundReadFrames
{
    /// <summary>QQMR registering CIO 1.05 (bit), DM 1000 (word), TIM 5 (CH: Completion Flag and PV).</summary>
    public const string Register = "@00QQMRCIO 000105,DM  1000CH,TIM 0005CH43*\r";

    /// <summary>The PLC's answer to <see cref="Register"/>: end code 00.</summary>
    public const string RegisterAnswer = "@00QQMR005F*\r";

    /// <summary>QQIR: read what is registered.</summary>
    public const string Read = "@00QQIR5B*\r";

    /// <summary>The answer to <see cref="Read"/>: CIO 1.05 on, DM 1000 = 1234 hex, TIM 5 flag off with PV 0042.</summary>
    public const string ReadAnswer = "@00QQIR001,1234,0004258*\r";

    /// <summary>W342 end code 19 (not executable): QQIR with nothing registered.</summary>
    public const string NothingRegistered = "@00QQIR1953*\r";
}
