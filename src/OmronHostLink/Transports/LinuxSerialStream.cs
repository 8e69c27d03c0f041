using System.Runtime.InteropServices;
using System.Text;
using static OmronHostLink.Transports.LinuxNative;

namespace OmronHostLink.Transports;

/// <summary>
/// A serial device (or pseudo-terminal) on Linux as a <see cref="Stream"/>, over a non-blocking file descriptor.
/// </summary>
/// <remarks>
/// <para>
/// Reading first tries a non-blocking <c>read()</c>. When nothing is waiting, the read parks a dedicated thread
/// (<see cref="TaskCreationOptions.LongRunning"/>, never a thread-pool thread) in <c>poll()</c> on two descriptors:
/// the tty and an <c>eventfd</c> that is signalled when the read's <see cref="CancellationToken"/> fires or the
/// stream is disposed. <c>poll()</c> has no timeout: there is no sleep-polling, and the thread wakes only for data,
/// a hang-up, cancellation or disposal. Writing works the same way with <c>POLLOUT</c> and a second eventfd.
/// </para>
/// <para>
/// VMIN is 1 and VTIME 0. With <c>O_NONBLOCK</c> that never blocks, but it makes the line discipline report "no data"
/// as <c>EAGAIN</c>; with VMIN 0 it would return 0, which could not be told apart from a hang-up. So a 0-byte read,
/// <c>EIO</c>, or <c>POLLHUP</c>/<c>POLLERR</c> with nothing to read all mean the port was lost, and surface as
/// <see cref="IOException"/> rather than an endless stream of empty reads.
/// </para>
/// <para>One read and one write may be in progress at the same time, as with other streams.</para>
/// </remarks>
internal sealed unsafe class LinuxSerialStream : Stream, IInputDiscardable
{
    private const int FIONREAD = 0x541B;

    private readonly string _portName;
    private readonly FileDescriptorHandle _tty;
    private readonly FileDescriptorHandle _readWake;
    private readonly FileDescriptorHandle _writeWake;
    private int _disposed;

    private LinuxSerialStream(string portName, FileDescriptorHandle tty, FileDescriptorHandle readWake, FileDescriptorHandle writeWake)
    {
        _portName = portName;
        _tty = tty;
        _readWake = readWake;
        _writeWake = writeWake;
    }

    /// <summary>True when this process's architecture uses the generic Linux termios layout and constants.</summary>
    public static bool IsSupportedArchitecture
    {
        get
        {
            Architecture architecture = RuntimeInformation.ProcessArchitecture;
            return architecture is Architecture.X64 or Architecture.Arm64 or Architecture.X86 or Architecture.Arm
                || architecture.ToString() is "RiscV64" or "LoongArch64";
        }
    }

    public static LinuxSerialStream Open(SerialLineSettings settings)
    {
        string name = settings.PortName;
        byte[] path = Encoding.UTF8.GetBytes(name + "\0");
        int fd;
        fixed (byte* p = path)
        {
            fd = LinuxNative.Open(p, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
        }

        if (fd < 0)
        {
            throw Unavailable(name, Marshal.GetLastWin32Error(), null);
        }

        var tty = new FileDescriptorHandle(fd);
        FileDescriptorHandle? readWake = null;
        FileDescriptorHandle? writeWake = null;
        try
        {
            Configure(fd, settings);
            readWake = CreateWakeEvent(name);
            writeWake = CreateWakeEvent(name);
            return new LinuxSerialStream(name, tty, readWake, writeWake);
        }
        catch
        {
            tty.Dispose();
            readWake?.Dispose();
            writeWake?.Dispose();
            throw;
        }
    }

    private static void Configure(int fd, SerialLineSettings settings)
    {
        string name = settings.PortName;
        Termios t;
        if (TcGetAttr(fd, &t) != 0)
        {
            throw Unavailable(name, Marshal.GetLastWin32Error(), "cannot read the line settings");
        }

        // Raw mode, as cfmakeraw() does, plus our own input parity check and flow control.
        t.c_iflag &= ~(IGNBRK | BRKINT | IGNPAR | PARMRK | INPCK | ISTRIP | INLCR | IGNCR | ICRNL | IUCLC | IXON | IXANY | IXOFF | IMAXBEL);
        t.c_oflag &= ~OPOST;
        t.c_lflag &= ~(ISIG | ICANON | ECHO | ECHOE | ECHOK | ECHONL | IEXTEN);
        t.c_cflag &= ~(CSIZE | CSTOPB | PARENB | PARODD | CRTSCTS);
        t.c_cflag |= CLOCAL | CREAD | (settings.DataBits == 7 ? CS7 : CS8);

        if (settings.Parity != SerialParity.None)
        {
            t.c_cflag |= PARENB;
            if (settings.Parity == SerialParity.Odd)
            {
                t.c_cflag |= PARODD;
            }

            // A character with a parity error is delivered as NUL, which no Host Link frame contains.
            t.c_iflag |= INPCK;
        }

        if (settings.StopBits == SerialStopBits.Two)
        {
            t.c_cflag |= CSTOPB;
        }

        switch (settings.Handshake)
        {
            case SerialHandshake.RequestToSend:
                t.c_cflag |= CRTSCTS;
                break;
            case SerialHandshake.XOnXOff:
                t.c_iflag |= IXON | IXOFF;
                t.c_cc[VSTART] = 0x11;
                t.c_cc[VSTOP] = 0x13;
                break;
        }

        t.c_cc[VMIN] = 1;
        t.c_cc[VTIME] = 0;

        uint speed = BaudConstant(settings.BaudRate);
        if (speed == 0 || CfSetISpeed(&t, speed) != 0 || CfSetOSpeed(&t, speed) != 0)
        {
            throw new SerialPortUnavailableException(name, $"baud rate {settings.BaudRate} is not supported", EINVAL, null);
        }

        if (TcSetAttr(fd, TCSANOW, &t) != 0)
        {
            throw Unavailable(name, Marshal.GetLastWin32Error(), $"cannot apply the line settings {settings.BaudRate} {settings.DataBits}{settings.Parity.ToString()[0]}{(int)settings.StopBits}");
        }

        // Modem-control lines are touched only when asked for: pseudo-terminals refuse these requests.
        if (settings.DtrEnable)
        {
            SetModemLine(fd, name, TIOCM_DTR, "DTR");
        }

        if (settings.RtsEnable)
        {
            SetModemLine(fd, name, TIOCM_RTS, "RTS");
        }
    }

    private static void SetModemLine(int fd, string name, int line, string lineName)
    {
        int bits = line;
        if (Ioctl(fd, TIOCMBIS, &bits) != 0)
        {
            throw Unavailable(name, Marshal.GetLastWin32Error(), $"cannot raise {lineName} ({lineName}Enable was set; pseudo-terminals do not support it)");
        }
    }

    private static FileDescriptorHandle CreateWakeEvent(string name)
    {
        int fd = EventFd(0, EFD_NONBLOCK | EFD_CLOEXEC);
        if (fd < 0)
        {
            throw Unavailable(name, Marshal.GetLastWin32Error(), "cannot create an eventfd");
        }

        return new FileDescriptorHandle(fd);
    }

    private static SerialPortUnavailableException Unavailable(string name, int errno, string? what)
    {
        string reason = what is null ? Describe(errno) : $"{what}: {Describe(errno)}";
        return new SerialPortUnavailableException(name, reason, errno, null);
    }

    public override bool CanRead => Volatile.Read(ref _disposed) == 0;

    public override bool CanWrite => Volatile.Read(ref _disposed) == 0;

    public override bool CanSeek => false;

    public override long Length => throw new NotSupportedException("A serial port has no length.");

    public override long Position
    {
        get => throw new NotSupportedException("A serial port has no position.");
        set => throw new NotSupportedException("A serial port has no position.");
    }

    /// <summary>Bytes received and not yet read (FIONREAD); for tests and diagnostics.</summary>
    internal int BytesToRead
    {
        get
        {
            bool added = false;
            try
            {
                _tty.DangerousAddRef(ref added);
                int count = 0;
                if (Ioctl(_tty.Fd, FIONREAD, &count) != 0)
                {
                    throw Failure("FIONREAD", Marshal.GetLastWin32Error());
                }

                return count;
            }
            finally
            {
                if (added)
                {
                    _tty.DangerousRelease();
                }
            }
        }
    }

    public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException("A serial port cannot seek.");

    public override void SetLength(long value) => throw new NotSupportedException("A serial port has no length.");

    /// <summary>Nothing to do: every write has been handed to the driver when it completes.</summary>
    public override void Flush() => ThrowIfDisposed();

    public override Task FlushAsync(CancellationToken cancellationToken)
    {
        if (cancellationToken.IsCancellationRequested)
        {
            return Task.FromCanceled(cancellationToken);
        }

        ThrowIfDisposed();
        return Task.CompletedTask;
    }

    public void DiscardInput()
    {
        bool added = false;
        try
        {
            _tty.DangerousAddRef(ref added);
            if (TcFlush(_tty.Fd, TCIFLUSH) != 0)
            {
                throw Failure("discard input", Marshal.GetLastWin32Error());
            }
        }
        finally
        {
            if (added)
            {
                _tty.DangerousRelease();
            }
        }
    }

    public override int Read(byte[] buffer, int offset, int count)
    {
        ValidateBuffer(buffer, offset, count);
        return ReadCore(new Span<byte>(buffer, offset, count), CancellationToken.None, mayWait: true);
    }

    public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
    {
        ValidateBuffer(buffer, offset, count);
        return ReadCoreAsync(new Memory<byte>(buffer, offset, count), cancellationToken);
    }

    public override void Write(byte[] buffer, int offset, int count)
    {
        ValidateBuffer(buffer, offset, count);
        WriteCore(new ReadOnlySpan<byte>(buffer, offset, count), CancellationToken.None, mayWait: true);
    }

    public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
    {
        ValidateBuffer(buffer, offset, count);
        return WriteCoreAsync(new ReadOnlyMemory<byte>(buffer, offset, count), cancellationToken);
    }

#if NET
    public override int Read(Span<byte> buffer) => ReadCore(buffer, CancellationToken.None, mayWait: true);

    public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        => new(ReadCoreAsync(buffer, cancellationToken));

    public override void Write(ReadOnlySpan<byte> buffer) => WriteCore(buffer, CancellationToken.None, mayWait: true);

    public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        => new(WriteCoreAsync(buffer, cancellationToken));
#endif

    private Task<int> ReadCoreAsync(Memory<byte> buffer, CancellationToken cancellationToken)
    {
        if (cancellationToken.IsCancellationRequested)
        {
            return Task.FromCanceled<int>(cancellationToken);
        }

        try
        {
            // Fast path: data already waiting costs no thread hop.
            int read = ReadCore(buffer.Span, cancellationToken, mayWait: false);
            if (read >= 0)
            {
                return Task.FromResult(read);
            }
        }
        catch (Exception ex)
        {
            return Task.FromException<int>(ex);
        }

        return Task.Factory.StartNew(
            static state =>
            {
                var (stream, memory, token) = ((LinuxSerialStream, Memory<byte>, CancellationToken))state!;
                return stream.ReadCore(memory.Span, token, mayWait: true);
            },
            (this, buffer, cancellationToken),
            cancellationToken,
            TaskCreationOptions.LongRunning | TaskCreationOptions.DenyChildAttach,
            TaskScheduler.Default);
    }

    private Task WriteCoreAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken)
    {
        if (cancellationToken.IsCancellationRequested)
        {
            return Task.FromCanceled(cancellationToken);
        }

        int written;
        try
        {
            // Fast path: a frame that fits in the driver's buffer is written without a thread hop.
            written = WriteCore(buffer.Span, cancellationToken, mayWait: false);
        }
        catch (Exception ex)
        {
            return Task.FromException(ex);
        }

        if (written == buffer.Length)
        {
            return Task.CompletedTask;
        }

        return Task.Factory.StartNew(
            static state =>
            {
                var (stream, memory, token) = ((LinuxSerialStream, ReadOnlyMemory<byte>, CancellationToken))state!;
                stream.WriteCore(memory.Span, token, mayWait: true);
            },
            (this, buffer.Slice(written), cancellationToken),
            cancellationToken,
            TaskCreationOptions.LongRunning | TaskCreationOptions.DenyChildAttach,
            TaskScheduler.Default);
    }

    /// <summary>Reads at least one byte; or, when <paramref name="mayWait"/> is false and nothing is waiting, returns -1.</summary>
    private int ReadCore(Span<byte> buffer, CancellationToken cancellationToken, bool mayWait)
    {
        if (buffer.IsEmpty)
        {
            ThrowIfDisposed();
            return 0;
        }

        bool ttyAdded = false;
        bool wakeAdded = false;
        CancellationTokenRegistration registration = default;
        bool registered = false;
        try
        {
            AddRef(_tty, ref ttyAdded);
            AddRef(_readWake, ref wakeAdded);
            bool hungUp = false;
            while (true)
            {
                ThrowIfDisposed();
                cancellationToken.ThrowIfCancellationRequested();

                nint n;
                fixed (byte* p = buffer)
                {
                    n = LinuxNative.Read(_tty.Fd, p, (nuint)buffer.Length);
                }

                if (n > 0)
                {
                    return (int)n;
                }

                if (n == 0)
                {
                    throw Lost(0);
                }

                int errno = Marshal.GetLastWin32Error();
                if (errno == EINTR)
                {
                    continue;
                }

                if (errno != EAGAIN)
                {
                    throw IsLoss(errno) ? Lost(errno) : Failure("read", errno);
                }

                if (hungUp)
                {
                    throw Lost(0);
                }

                if (!mayWait)
                {
                    return -1;
                }

                if (cancellationToken.CanBeCanceled && !registered)
                {
                    registration = cancellationToken.Register(static s => ((LinuxSerialStream)s!).Signal(((LinuxSerialStream)s!)._readWake), this);
                    registered = true;
                    continue; // re-check the token now that a cancellation will wake the poll
                }

                hungUp = WaitFor(POLLIN, _readWake);
            }
        }
        finally
        {
            registration.Dispose();
            if (wakeAdded)
            {
                _readWake.DangerousRelease();
            }

            if (ttyAdded)
            {
                _tty.DangerousRelease();
            }
        }
    }

    /// <summary>Writes all of <paramref name="buffer"/>; or, when <paramref name="mayWait"/> is false, as much as the driver takes now.</summary>
    private int WriteCore(ReadOnlySpan<byte> buffer, CancellationToken cancellationToken, bool mayWait)
    {
        bool ttyAdded = false;
        bool wakeAdded = false;
        CancellationTokenRegistration registration = default;
        bool registered = false;
        int written = 0;
        try
        {
            AddRef(_tty, ref ttyAdded);
            AddRef(_writeWake, ref wakeAdded);
            bool hungUp = false;
            while (written < buffer.Length)
            {
                ThrowIfDisposed();
                cancellationToken.ThrowIfCancellationRequested();

                nint n;
                fixed (byte* p = buffer)
                {
                    n = LinuxNative.Write(_tty.Fd, p + written, (nuint)(buffer.Length - written));
                }

                if (n > 0)
                {
                    written += (int)n;
                    hungUp = false;
                    continue;
                }

                int errno = n == 0 ? EAGAIN : Marshal.GetLastWin32Error();
                if (errno == EINTR)
                {
                    continue;
                }

                if (errno != EAGAIN)
                {
                    throw IsLoss(errno) ? Lost(errno) : Failure("write", errno);
                }

                if (hungUp)
                {
                    throw Lost(0);
                }

                if (!mayWait)
                {
                    return written;
                }

                if (cancellationToken.CanBeCanceled && !registered)
                {
                    registration = cancellationToken.Register(static s => ((LinuxSerialStream)s!).Signal(((LinuxSerialStream)s!)._writeWake), this);
                    registered = true;
                    continue;
                }

                hungUp = WaitFor(POLLOUT, _writeWake);
            }

            return written;
        }
        finally
        {
            registration.Dispose();
            if (wakeAdded)
            {
                _writeWake.DangerousRelease();
            }

            if (ttyAdded)
            {
                _tty.DangerousRelease();
            }
        }
    }

    /// <summary>
    /// Blocks in poll() until the tty is ready for <paramref name="events"/>, reports a hang-up or error, or
    /// <paramref name="wake"/> is signalled (cancellation or disposal; the caller re-checks both).
    /// </summary>
    /// <returns>True when the tty reported POLLHUP, POLLERR or POLLNVAL.</returns>
    private bool WaitFor(short events, FileDescriptorHandle wake)
    {
        PollFd* fds = stackalloc PollFd[2];
        fds[0] = new PollFd { fd = _tty.Fd, events = events };
        fds[1] = new PollFd { fd = wake.Fd, events = POLLIN };
        while (Poll(fds, 2, -1) < 0)
        {
            int errno = Marshal.GetLastWin32Error();
            if (errno != EINTR)
            {
                throw Failure("poll", errno);
            }
        }

        if (fds[1].revents != 0)
        {
            // Reset the eventfd; the caller's loop re-checks disposal and its token before waiting again,
            // so a signal meant for an earlier, already finished operation only costs one extra turn.
            ulong value;
            _ = LinuxNative.Read(wake.Fd, (byte*)&value, sizeof(ulong));
        }

        return (fds[0].revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
    }

    private void Signal(FileDescriptorHandle wake)
    {
        bool added = false;
        try
        {
            wake.DangerousAddRef(ref added);
            ulong one = 1;
            _ = LinuxNative.Write(wake.Fd, (byte*)&one, sizeof(ulong));
        }
        catch (ObjectDisposedException)
        {
            // Already closed: nobody is waiting on it.
        }
        finally
        {
            if (added)
            {
                wake.DangerousRelease();
            }
        }
    }

    private void AddRef(FileDescriptorHandle handle, ref bool added)
    {
        try
        {
            handle.DangerousAddRef(ref added);
        }
        catch (ObjectDisposedException)
        {
            throw Disposed();
        }
    }

    private static bool IsLoss(int errno) => errno is EIO or ENXIO or ENODEV;

    private IOException Lost(int errno) => new(
        $"Serial port {_portName} was closed or lost: the device hung up (a USB adapter unplugged, or the other end of a pseudo-terminal closed)"
        + (errno == 0 ? "." : $"; {Describe(errno)}."));

    private IOException Failure(string operation, int errno) =>
        new($"Serial port {_portName}: {operation} failed: {Describe(errno)}.");

    private ObjectDisposedException Disposed() => new(GetType().Name, $"Serial port {_portName} has been closed.");

    private void ThrowIfDisposed()
    {
        if (Volatile.Read(ref _disposed) != 0)
        {
            throw Disposed();
        }
    }

    private static void ValidateBuffer(byte[] buffer, int offset, int count)
    {
        Guard.NotNull(buffer);
        if (offset < 0 || count < 0 || count > buffer.Length - offset)
        {
            throw new ArgumentOutOfRangeException(
                offset < 0 ? nameof(offset) : nameof(count),
                $"offset {offset} and count {count} do not describe a range of the {buffer.Length}-byte buffer.");
        }
    }

    protected override void Dispose(bool disposing)
    {
        if (Interlocked.Exchange(ref _disposed, 1) == 0)
        {
            // Wake any read or write parked in poll(); each sees the flag and throws ObjectDisposedException.
            // The descriptors close when the last system call using them has released its reference.
            Signal(_readWake);
            Signal(_writeWake);
            _tty.Dispose();
            _readWake.Dispose();
            _writeWake.Dispose();
        }

        base.Dispose(disposing);
    }
}
