using System.Net.Sockets;

namespace OmronHostLink.Transports;

/// <summary>
/// A TCP connection to a serial-device server (or the simulator). It connects on first use and reconnects on the next
/// call after a drop. Nagle's delay is off: Host Link frames are small and every one waits for an answer.
/// </summary>
public sealed class TcpTransport : IHostLinkTransport
{
    private TcpClient? _client;

    /// <summary>Creates the transport; nothing connects until the first exchange.</summary>
    public TcpTransport(string host, int port, TimeSpan? connectTimeout = null, LineTiming? lineTiming = null)
    {
        Guard.NotNull(host);
        if (SettingRules.Host(host) is { } badHost)
        {
            throw new ArgumentException($"The host {badHost}.", nameof(host));
        }

        if (SettingRules.TcpPort(port) is { } badPort)
        {
            throw new ArgumentOutOfRangeException(nameof(port), port, $"The port {badPort}.");
        }

        if (connectTimeout is { } t && SettingRules.ConnectTimeout(t) is { } badTimeout)
        {
            throw new ArgumentOutOfRangeException(nameof(connectTimeout), t, $"The connect timeout {badTimeout}.");
        }

        Host = host;
        Port = port;
        ConnectTimeout = connectTimeout ?? TimeSpan.FromSeconds(5);
        LineTiming = lineTiming;
    }

    /// <summary>The server's host name or address.</summary>
    public string Host { get; }

    /// <summary>The server's port.</summary>
    public int Port { get; }

    /// <summary>How long a connection attempt may take.</summary>
    public TimeSpan ConnectTimeout { get; }

    /// <inheritdoc/>
    public string Description => $"{Host}:{Port}";

    /// <inheritdoc/>
    public LineTiming? LineTiming { get; }

    /// <summary>Parses <c>host:port</c>.</summary>
    /// <exception cref="FormatException">The text is not host:port with a port 1-65535.</exception>
    public static (string Host, int Port) ParseEndpoint(string text)
    {
        Guard.NotNull(text);
        return SettingRules.TryParseEndpoint(text, out string host, out int port, out string? error)
            ? (host, port)
            : throw new FormatException(error + ".");
    }

    /// <inheritdoc/>
    public async ValueTask<Stream> OpenAsync(CancellationToken cancellationToken)
    {
        if (_client is { Connected: true } c)
        {
            return c.GetStream();
        }

        _client?.Dispose();
        var client = new TcpClient { NoDelay = true };
        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        timeout.CancelAfter(ConnectTimeout);
        try
        {
#if NET
            await client.ConnectAsync(Host, Port, timeout.Token).ConfigureAwait(false);
#else
            using (timeout.Token.Register(client.Dispose))
            {
                await client.ConnectAsync(Host, Port).ConfigureAwait(false);
            }
#endif
        }
        catch (Exception e) when (e is SocketException or OperationCanceledException or ObjectDisposedException && !cancellationToken.IsCancellationRequested)
        {
            client.Dispose();
            string why = e is SocketException se ? se.Message : $"no connection within {ConnectTimeout.TotalSeconds:0.#} s";
            throw new HostLinkConnectionException($"Cannot connect to {Description}: {why}.", e);
        }

        _client = client;
        return client.GetStream();
    }

    /// <inheritdoc/>
    public ValueTask CloseAsync()
    {
        _client?.Dispose();
        _client = null;
        return default;
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => CloseAsync();
}
