using System.Net.Sockets;
using System.Text;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The service manager's end of sd_notify: a Unix datagram socket bound to a fresh path in the temp directory. A process
/// started with <c>NOTIFY_SOCKET</c> set to <see cref="Path"/> sends its state changes ("READY=1", "STOPPING=1") here.
/// </summary>
internal sealed class NotifySocket : IDisposable
{
    private readonly Socket _socket;

    private NotifySocket(Socket socket, string path)
    {
        _socket = socket;
        Path = path;
    }

    /// <summary>The socket's path, for <c>NOTIFY_SOCKET</c>.</summary>
    public string Path { get; }

    /// <summary>Binds a new socket (the path stays short: sun_path holds 108 bytes).</summary>
    public static NotifySocket Bind()
    {
        string path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), $"ohl-notify-{Guid.NewGuid():N}.sock");
        var socket = new Socket(AddressFamily.Unix, SocketType.Dgram, ProtocolType.Unspecified);
        try
        {
            socket.Bind(new UnixDomainSocketEndPoint(path));
        }
        catch
        {
            socket.Dispose();
            throw;
        }

        return new NotifySocket(socket, path);
    }

    /// <summary>The next datagram as text, or null if none arrives within <paramref name="timeout"/>.</summary>
    public async Task<string?> ReceiveAsync(TimeSpan timeout)
    {
        var buffer = new byte[4096];
        using var cts = new CancellationTokenSource(timeout);
        try
        {
            int n = await _socket.ReceiveAsync(buffer, SocketFlags.None, cts.Token);
            return Encoding.UTF8.GetString(buffer, 0, n);
        }
        catch (OperationCanceledException)
        {
            return null;
        }
    }

    /// <summary>How many bytes wait unread (0: nothing was sent since the last receive).</summary>
    public int Available => _socket.Available;

    public void Dispose()
    {
        _socket.Dispose();
        File.Delete(Path);
    }
}
