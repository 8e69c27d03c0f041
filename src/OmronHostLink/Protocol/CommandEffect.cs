namespace OmronHostLink.Protocol;

/// <summary>What repeating a command whose answer was lost would do: the fact a retry policy is built on.</summary>
internal enum CommandEffect
{
    /// <summary>Changes nothing in the PLC (reads, TS): repeating it is harmless.</summary>
    ReadOnly,

    /// <summary>Sets memory to given values: repeating it leaves the same state, but the PLC program may have changed it in between.</summary>
    Idempotent,

    /// <summary>Changes state so that a repeat may not equal one execution (mode changes, clearing errors, forcing, abort).</summary>
    NotRepeatable,
}
