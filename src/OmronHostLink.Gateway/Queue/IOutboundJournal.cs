namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// What the outbound queue keeps outside the process, told of every message it takes and lets go, in the queue's order
/// and under its lock: a durable copy of the messages (<see cref="SqliteOutboundJournal"/>) or only how many wait
/// (<see cref="UnsentRecord"/>). A journal never throws: a store it cannot write costs durability, never a value.
/// </summary>
internal interface IOutboundJournal
{
    /// <summary>The messages a previous run left, oldest first, with their <see cref="OutboundMessage.Sequence"/> and <see cref="OutboundMessage.QueuedAt"/>.</summary>
    IReadOnlyList<OutboundMessage> Load();

    /// <summary>A message joined the queue's tail.</summary>
    void Added(OutboundMessage message);

    /// <summary>A message left the queue: acknowledged by the broker, or dropped (full, too old).</summary>
    void Removed(OutboundMessage message);
}
