using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Status;

/// <summary>The Outputs view: how each configured output stands (<see cref="IOutputStatus"/>).</summary>
/// <param name="outputs">Every output that tells how it stands.</param>
/// <param name="time">The clock.</param>
internal sealed class OutputsView(IEnumerable<IOutputStatus> outputs, TimeProvider time)
{
    private readonly IOutputStatus[] _outputs = outputs.ToArray();

    /// <summary>The view now.</summary>
    public OutputsDocument Snapshot() => new() { Now = time.GetUtcNow(), Outputs = _outputs.Select(o => o.Status()).ToList() };
}
