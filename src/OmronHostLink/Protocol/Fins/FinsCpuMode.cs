namespace OmronHostLink.Protocol.Fins;

/// <summary>Operating modes as FINS codes them (0401 RUN parameter, 0601 status response).</summary>
public enum FinsCpuMode
{
    /// <summary>00: PROGRAM mode.</summary>
    Program = 0x00,

    /// <summary>02: MONITOR mode.</summary>
    Monitor = 0x02,

    /// <summary>04: RUN mode.</summary>
    Run = 0x04,
}
