namespace OmronHostLink.Transports;

/// <summary>
/// A stream whose pending, not yet read input can be thrown away, such as the receive buffer of a serial port.
/// The Host Link link calls it when it resynchronises after a failed transaction so that a late or stale
/// response can never be taken as the answer to the next request.
/// </summary>
public interface IInputDiscardable
{
    /// <summary>Discards every byte that has been received but not yet read.</summary>
    /// <exception cref="ObjectDisposedException">The stream has been disposed.</exception>
    /// <exception cref="IOException">The device refused the request.</exception>
    void DiscardInput();
}
