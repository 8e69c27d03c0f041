namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// An output that tells how it stands: its broker connection, what waits to be sent and when it last sent. The status
/// page reads every output through this, so an output's broker handling can change without the page changing.
/// Implementations answer at once from what they hold, without I/O.
/// </summary>
internal interface IOutputStatus
{
    /// <summary>How the output stands now.</summary>
    OutputStatus Status();
}
