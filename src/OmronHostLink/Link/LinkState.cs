namespace OmronHostLink.Link;

/// <summary>Where the link stands between transactions.</summary>
/// <remarks>
/// A transaction's outcome is the next state (<see cref="TransactionAttempt.After"/>): the values are ordered from in
/// step to furthest out of it, and a failure never moves the link back towards <see cref="Ready"/>.
/// <code>
/// Closed ──open──▶ Ready ──complete answer (values or an end code)──▶ Ready
/// Ready ──timeout, damage, cancellation──▶ NeedsResync ──TS fence echoed──▶ Ready
/// Ready ──failure inside a multi-frame exchange──▶ NeedsInitialize ──@** sent──▶ NeedsResync
/// NeedsResync ──fence unanswered──▶ NeedsResync (the next call fences again, at its own unit)
/// Ready / NeedsResync / NeedsInitialize ──stream lost──▶ Broken ──transport closed at once──▶ Closed
/// any ──DisposeAsync──▶ Disposed
/// </code>
/// </remarks>
internal enum LinkState
{
    /// <summary>No stream: the next transaction opens the transport.</summary>
    Closed,

    /// <summary>Open and in step with the PLC: the next transaction starts at once.</summary>
    Ready,

    /// <summary>
    /// Open, but the last exchange failed: a late answer to it may still come, so the next transaction first discards
    /// what is buffered and fences with TS.
    /// </summary>
    NeedsResync,

    /// <summary>
    /// Open, and a multi-frame exchange was cut: a PLC may hold the rest of an answer (or wait for the rest of a
    /// command), so the next transaction first sends <c>@**</c> (INITIALIZE), then resynchronises.
    /// </summary>
    NeedsInitialize,

    /// <summary>The stream failed: it is closed at once, and the next transaction reopens the transport.</summary>
    Broken,

    /// <summary>Disposed: every call fails.</summary>
    Disposed,
}
