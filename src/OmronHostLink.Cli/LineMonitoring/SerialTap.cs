using System.Runtime.InteropServices;
using System.Threading.Channels;
using Microsoft.Win32.SafeHandles;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// Listens to one serial port without ever writing to it: a thread of its own reads whatever arrives and hands it on,
/// stamped with the time the read returned and the reader's watermark (<see cref="TapChunk.Clear"/>), to a channel that
/// never blocks the reader (a slow console cannot make the port's buffer overflow). A quiet port's watermark is handed
/// on by itself each time a poll finds nothing.
/// </summary>
/// <remarks>
/// The port's speed and format are set with System.IO.Ports (a pseudo-terminal in the 8-bit framing it holds). On Linux
/// and macOS the bytes are read from a descriptor of the device opened just before, with blocking reads: System.IO.Ports
/// serves reads from one polling thread that sleeps a millisecond whenever no read is queued, and bytes arriving then
/// are stamped up to a millisecond late, which is the whole error a latency reading may have. The descriptor is opened
/// before System.IO.Ports, which then claims the device exclusively. On Linux the reader asks for real-time scheduling
/// where it is allowed (<see cref="RealTimeScheduling"/>). On Windows the port's own stream is read, with blocking
/// reads that cannot prove the port quiet (<see cref="ProvesQuiet"/>).
/// </remarks>
internal sealed class SerialTap : IDisposable
{
    private const short PollIn = 0x1;
    /// <summary>How long a poll waits: a quiet port's watermark (<see cref="TapChunk.Clear"/>) moves this often, and a frame of the other port waits at most about this long for it.</summary>
    private const int PollMilliseconds = 20;

    private readonly int _source;
    private readonly ChannelWriter<TapChunk> _output;
    private readonly SerialTransport _port;
    private readonly FileStream? _raw;
    private readonly Stream _stream;
    private readonly Thread _reader;
    private volatile bool _stopping;

    private SerialTap(int source, SerialLineSettings settings, ChannelWriter<TapChunk> output, FileStream? raw, SerialTransport port, Stream stream)
    {
        _source = source;
        _output = output;
        _raw = raw;
        _port = port;
        _stream = stream;
        Description = settings.ToString();
        _reader = new Thread(Read) { IsBackground = true, Name = $"hostlink tap {settings.PortName}" };
    }

    /// <summary>The port and its settings.</summary>
    public string Description { get; }

    /// <summary>Bytes read so far.</summary>
    public long Bytes => Interlocked.Read(ref _bytes);

    private long _bytes;

    /// <summary>Why reading stopped, when the port failed; null while it reads or after <see cref="Dispose"/>.</summary>
    public Exception? Failure { get; private set; }

    /// <summary>Opens the port at <paramref name="settings"/> and starts reading it.</summary>
    /// <exception cref="HostLinkConnectionException">The port cannot be opened; the message names it and says why.</exception>
    public static async Task<SerialTap> OpenAsync(int source, SerialLineSettings settings, ChannelWriter<TapChunk> output, CancellationToken cancellationToken)
    {
        FileStream? raw = null;
        if (!RuntimeInformation.IsOSPlatform(OSPlatform.Windows))
        {
            try
            {
                raw = new FileStream(new SafeFileHandle(OpenReadOnly(settings.PortName), ownsHandle: true), FileAccess.Read, bufferSize: 0);
            }
            catch (IOException e)
            {
                throw new HostLinkConnectionException($"Cannot open {settings.PortName} to listen: {e.Message}", e);
            }
        }

        var port = new SerialTransport(settings);
        Stream stream;
        try
        {
            stream = await port.OpenAsync(cancellationToken).ConfigureAwait(false);
        }
        catch
        {
            raw?.Dispose();
            throw;
        }

        var tap = new SerialTap(source, settings, output, raw, port, stream);
        tap._reader.Start();
        return tap;
    }

    /// <summary>Stops reading and closes the port.</summary>
    public void Dispose()
    {
        _stopping = true;
        _port.Dispose();
        if (_raw is null)
        {
            // Closing the port ended the blocking read.
            _reader.Join(TimeSpan.FromSeconds(2));
        }
        else
        {
            // The reader polls in short steps and sees the flag.
            _reader.Join(TimeSpan.FromMilliseconds(PollMilliseconds * 5));
            _raw.Dispose();
        }
    }

    /// <summary>Whether the reader proves its port quiet with polls that time out (not on Windows; see <see cref="LineMonitor"/>).</summary>
    public bool ProvesQuiet => _raw is not null;

    /// <summary>Whether the reader thread runs with real-time scheduling (see the remarks).</summary>
    public bool RealTime { get; private set; }

    private void Read()
    {
        RealTime = RealTimeScheduling.TryRaiseThisThread();
        var buffer = new byte[4096];
        long clear = 0;
        try
        {
            while (!_stopping)
            {
                if (_raw is not null)
                {
                    long polled = System.Diagnostics.Stopwatch.GetTimestamp();
                    int ready = Poll(_raw.SafeFileHandle);
                    if (ready == 0)
                    {
                        // Nothing was waiting when the poll began, nor came before it timed out: every byte that reached
                        // the port before the poll began has been handed over.
                        clear = polled;
                        _output.TryWrite(new TapChunk(_source, [], polled, clear));
                    }

                    if (ready <= 0)
                    {
                        continue;
                    }
                }

                long entered = System.Diagnostics.Stopwatch.GetTimestamp();
                int n = _raw is not null ? _raw.Read(buffer, 0, buffer.Length) : _stream.Read(buffer, 0, buffer.Length);
                long ticks = System.Diagnostics.Stopwatch.GetTimestamp();
                if (n <= 0)
                {
                    throw new IOException("the device hung up (it is gone, or the other end of a pseudo-terminal closed)");
                }

                if (n < buffer.Length)
                {
                    // A read that did not fill the buffer took all there was: every byte that had come before it began.
                    clear = entered;
                }

                Interlocked.Add(ref _bytes, n);
                _output.TryWrite(new TapChunk(_source, buffer.AsSpan(0, n).ToArray(), ticks, clear));
            }
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException or UnauthorizedAccessException)
        {
            if (!_stopping)
            {
                Failure = e;
                _output.TryComplete(new HostLinkConnectionException($"Lost {Description}: {e.Message}", e));
            }
        }
    }

    /// <summary>Waits up to <see cref="PollMilliseconds"/> for bytes to read: 1 when there are, 0 when none came, -1 when a signal interrupted the wait.</summary>
    private static int Poll(SafeFileHandle handle)
    {
        var fd = new PollFd { Fd = (int)handle.DangerousGetHandle(), Events = PollIn };
        int ready = Poll(ref fd, 1, PollMilliseconds);
        if (ready < 0)
        {
            int errno = Marshal.GetLastPInvokeError();
            if (errno == 4)
            {
                // EINTR: a signal; poll again.
                return -1;
            }

            throw new IOException($"poll failed (errno {errno}).");
        }

        return ready > 0 ? 1 : 0;
    }

    private static IntPtr OpenReadOnly(string path)
    {
        // O_RDONLY | O_NOCTTY | O_CLOEXEC: a serial device must not become the monitor's controlling terminal.
        int flags = RuntimeInformation.IsOSPlatform(OSPlatform.OSX) ? 0x20000 | 0x1000000 : 0x100 | 0x80000;
        int fd = OpenNative(path, flags);
        if (fd < 0)
        {
            int errno = Marshal.GetLastPInvokeError();
            throw new IOException(errno switch
            {
                2 => "there is no such device",
                13 => "permission denied (on Linux, add the user to the dialout group)",
                16 => "the device is in use by another program",
                _ => $"open failed (errno {errno})",
            });
        }

        return fd;
    }

    [StructLayout(LayoutKind.Sequential)]
    private struct PollFd
    {
        public int Fd;
        public short Events;
        public short Revents;
    }

    [DllImport("libc", EntryPoint = "poll", SetLastError = true)]
    private static extern int Poll(ref PollFd fds, uint count, int timeout);

    [DllImport("libc", EntryPoint = "open", SetLastError = true, CharSet = CharSet.Ansi, BestFitMapping = false, ThrowOnUnmappableChar = true)]
    private static extern int OpenNative(string path, int flags);
}
