namespace OmronHostLink;

/// <summary>The operating mode of the CPU Unit.</summary>
public enum PlcMode
{
    /// <summary>PROGRAM: the program does not run; memory may be changed freely.</summary>
    Program,

    /// <summary>MONITOR: the program runs and memory may be changed online.</summary>
    Monitor,

    /// <summary>RUN: the program runs; C-mode area writes are refused.</summary>
    Run,
}
