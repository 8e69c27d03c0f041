namespace OmronHostLink.Gateway.Outputs;

/// <summary>The state of a link as the worker sees it.</summary>
public enum LinkState
{
    /// <summary>The link is polled and every PLC unit on it answers.</summary>
    Online,

    /// <summary>The link is polled but at least one PLC unit on it does not answer (timeout, lost connection, damaged frames).</summary>
    CommError,

    /// <summary>The link is not polled: the worker is stopping, or the link could not be set up.</summary>
    Offline,
}
