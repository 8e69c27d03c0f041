namespace OmronHostLink;

/// <summary>
/// The Host Link-compatible device mode of a Serial Communications Board or Unit (CS1W-SCB, CS1W-SCU, CJ1W-SCU) of unit
/// version 1.2 or later: which older Host Link device its answers imitate, so that a host program written for that
/// device reads them unchanged (SCU operation manual W336, section 4-6-2). The modes differ in how many words an answer
/// frame of RR, RL, RH, RC, RD and RJ carries, how many completion flags an RG answer frame carries, and whether MS
/// sends the 16 FAL/FALS message characters (as spaces) when no FAL/FALS has run. docs/models.md has the table.
/// </summary>
public enum HostLinkCompatibleMode
{
    /// <summary>
    /// Mode A (CS/CJ/C), the unit's default and the framing of the CPU Units' own ports: 30 words in a first answer
    /// frame and 31 in each later one, RG 121 and 125 flags, MS without message characters when none is set.
    /// </summary>
    ModeA,

    /// <summary>
    /// Mode B (CVM1/CV: CVM1/CV CPU ports, CV500-LK201): framed as mode A, but MS always carries the 16 message
    /// characters, spaces when no FAL/FALS has run.
    /// </summary>
    ModeB,

    /// <summary>
    /// Mode C (C200H Host Link Units C200H-LK101/201/202): 29 words in a first answer frame and 30 in each later one,
    /// RG 89 flags a frame, MS without message characters when none is set.
    /// </summary>
    ModeC,

    /// <summary>
    /// Mode D (C500/C120 Host Link Units C500-LK101/201/103/203, C120-LK101/201/202): 29 words in a first answer frame
    /// and 30 in each later one, RG 89 flags in the first frame. What its later RG frames carry and its MS form were
    /// not found in a manual page: the client does not check those, and the simulator does not emulate this mode.
    /// </summary>
    ModeD,
}
