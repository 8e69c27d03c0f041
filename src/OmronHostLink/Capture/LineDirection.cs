namespace OmronHostLink.Capture;

/// <summary>Which way bytes crossed a Host Link line.</summary>
internal enum LineDirection : byte
{
    /// <summary>Not known: a recorder that hears both directions on one wire and could not tell.</summary>
    Unknown = 0,

    /// <summary>From the host to the PLC: commands, and the bare CR asking for an answer's next frame.</summary>
    ToPlc = 1,

    /// <summary>From the PLC to the host: answers, and the bare CR asking for a command's next frame.</summary>
    FromPlc = 2,
}
