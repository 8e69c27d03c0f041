namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// What 2301 FORCED SET/RESET does to one bit (the set/reset designation). Only <see cref="ForceReset"/> and
/// <see cref="ForceSet"/> are confirmed by two sources; the release variants are [unverified].
/// </summary>
public enum FinsForceAction
{
    /// <summary>0000: force the bit OFF.</summary>
    ForceReset = 0x0000,

    /// <summary>0001: force the bit ON.</summary>
    ForceSet = 0x0001,

    /// <summary>8000: turn the bit OFF and release its forced status [unverified].</summary>
    ReleaseToOff = 0x8000,

    /// <summary>8001: turn the bit ON and release its forced status [unverified].</summary>
    ReleaseToOn = 0x8001,

    /// <summary>FFFF: release the forced status, keeping the bit's value [unverified].</summary>
    Release = 0xFFFF,
}
