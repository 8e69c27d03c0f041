namespace OmronHostLink;

/// <summary>The command set used to reach the PLC over a Host Link line.</summary>
public enum HostLinkCommandSet
{
    /// <summary>C-mode commands (RD, WD, RR, …): simple, but with narrower address ranges than FINS.</summary>
    CMode,

    /// <summary>FINS commands carried in Host Link <c>FA</c> frames: the whole of every area.</summary>
    Fins,
}
