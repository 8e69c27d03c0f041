namespace OmronHostLink.Transports;

/// <summary>
/// Where the link's bytes travel: a serial port, a TCP serial-device server, or any stream. The link asks for a stream
/// when it has none, and again after the previous one was lost (a transport that can reopen does so then).
/// </summary>
public interface IHostLinkTransport : IAsyncDisposable
{
    /// <summary>A short description for messages and logs (port name, host:port).</summary>
    string Description { get; }

    /// <summary>The line's character timing when the transport knows it (a serial port); null to use the client's option.</summary>
    LineTiming? LineTiming { get; }

    /// <summary>Opens (or reopens) the stream.</summary>
    /// <exception cref="HostLinkConnectionException">The stream cannot be opened; the message names the port or host and the reason.</exception>
    ValueTask<Stream> OpenAsync(CancellationToken cancellationToken);

    /// <summary>Tells the transport the stream it handed out is broken; the next <see cref="OpenAsync"/> makes a new one if it can.</summary>
    ValueTask CloseAsync();
}
