using System.Runtime.InteropServices;
using Microsoft.Win32.SafeHandles;
using static OmronHostLink.Transports.WindowsNative;

namespace OmronHostLink.Transports;

/// <summary>
/// A COM port on Windows as a <see cref="Stream"/>: the handle is opened for overlapped I/O and wrapped in an
/// unbuffered asynchronous <see cref="FileStream"/>, whose ReadAsync/WriteAsync cancel the pending I/O (CancelIoEx)
/// when their token fires.
/// </summary>
/// <remarks>
/// Exercised only on Windows: the Linux CI compiles this file but cannot run it.
/// The comm timeouts make a read complete as soon as at least one byte has arrived; if the long total timeout
/// expires first the driver completes it with 0 bytes, and the read is simply issued again.
/// </remarks>
internal sealed class WindowsSerialStream : Stream, IInputDiscardable
{
    // ReadTotalTimeoutConstant: how long one read waits for its first byte before it is re-issued.
    private const uint ReadReissueMilliseconds = 60 * 60 * 1000;

    private readonly string _portName;
    private readonly SafeFileHandle _handle;
    private readonly FileStream _file;
    private int _disposed;

    private WindowsSerialStream(string portName, SafeFileHandle handle, FileStream file)
    {
        _portName = portName;
        _handle = handle;
        _file = file;
    }

    public static WindowsSerialStream Open(SerialLineSettings settings)
    {
        string name = settings.PortName;
        string device = name.StartsWith(@"\\", StringComparison.Ordinal) ? name : @"\\.\" + name;
        SafeFileHandle handle = CreateFile(device, GENERIC_READ | GENERIC_WRITE, 0, IntPtr.Zero, OPEN_EXISTING, FILE_FLAG_OVERLAPPED, IntPtr.Zero);
        if (handle.IsInvalid)
        {
            int error = Marshal.GetLastWin32Error();
            handle.Dispose();
            throw new SerialPortUnavailableException(name, Describe(error), error, null);
        }

        try
        {
            Configure(handle, settings);
            var file = new FileStream(handle, FileAccess.ReadWrite, 1, isAsync: true);
            return new WindowsSerialStream(name, handle, file);
        }
        catch
        {
            handle.Dispose();
            throw;
        }
    }

    private static void Configure(SafeFileHandle handle, SerialLineSettings settings)
    {
        string name = settings.PortName;
        var dcb = new Dcb { DCBlength = (uint)Marshal.SizeOf<Dcb>() };
        if (!GetCommState(handle, ref dcb))
        {
            throw Unavailable(name, "cannot read the line settings; is it a serial port?");
        }

        dcb.BaudRate = (uint)settings.BaudRate;
        dcb.ByteSize = (byte)settings.DataBits;
        dcb.Parity = settings.Parity switch
        {
            SerialParity.Even => EVENPARITY,
            SerialParity.Odd => ODDPARITY,
            _ => NOPARITY,
        };
        dcb.StopBits = settings.StopBits == SerialStopBits.Two ? TWOSTOPBITS : ONESTOPBIT;

        uint flags = dcb.Flags & ~(fParity | fOutxCtsFlow | fOutxDsrFlow | fDtrControlMask | fDsrSensitivity
            | fOutX | fInX | fErrorChar | fNull | fRtsControlMask | fAbortOnError);
        flags |= fBinary | fTXContinueOnXoff;
        if (settings.Parity != SerialParity.None)
        {
            flags |= fParity;
        }

        if (settings.DtrEnable)
        {
            flags |= fDtrControlEnable;
        }

        switch (settings.Handshake)
        {
            case SerialHandshake.RequestToSend:
                flags |= fOutxCtsFlow | fRtsControlHandshake;
                break;
            case SerialHandshake.XOnXOff:
                flags |= fOutX | fInX;
                dcb.XonChar = 0x11;
                dcb.XoffChar = 0x13;
                break;
        }

        if (settings.RtsEnable)
        {
            flags |= fRtsControlEnable;
        }

        dcb.Flags = flags;
        if (!SetCommState(handle, ref dcb))
        {
            throw Unavailable(name, $"cannot apply the line settings {settings}");
        }

        var timeouts = new CommTimeouts
        {
            ReadIntervalTimeout = MAXDWORD,
            ReadTotalTimeoutMultiplier = MAXDWORD,
            ReadTotalTimeoutConstant = ReadReissueMilliseconds,
            WriteTotalTimeoutMultiplier = 0,
            WriteTotalTimeoutConstant = 0,
        };
        if (!SetCommTimeouts(handle, ref timeouts))
        {
            throw Unavailable(name, "cannot set the read timeouts");
        }
    }

    private static SerialPortUnavailableException Unavailable(string name, string what)
    {
        int error = Marshal.GetLastWin32Error();
        return new SerialPortUnavailableException(name, $"{what}: {Describe(error)}", error, null);
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

    public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException("A serial port cannot seek.");

    public override void SetLength(long value) => throw new NotSupportedException("A serial port has no length.");

    public override void Flush()
    {
        ThrowIfDisposed();
        _file.Flush();
    }

    public override Task FlushAsync(CancellationToken cancellationToken)
    {
        ThrowIfDisposed();
        return _file.FlushAsync(cancellationToken);
    }

    public void DiscardInput()
    {
        ThrowIfDisposed();
        if (!PurgeComm(_handle, PURGE_RXCLEAR))
        {
            int error = Marshal.GetLastWin32Error();
            throw new IOException($"Serial port {_portName}: discard input failed: {Describe(error)}.");
        }
    }

    public override int Read(byte[] buffer, int offset, int count)
    {
        ThrowIfDisposed();
        while (true)
        {
            int read = _file.Read(buffer, offset, count);
            if (read > 0 || count == 0)
            {
                return read;
            }

            ThrowIfDisposed();
        }
    }

    public override async Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
    {
        ThrowIfDisposed();
        while (true)
        {
            int read;
            try
            {
                read = await _file.ReadAsync(buffer, offset, count, cancellationToken).ConfigureAwait(false);
            }
            catch (Exception ex) when (Volatile.Read(ref _disposed) != 0 && ex is not OperationCanceledException)
            {
                throw new ObjectDisposedException(GetType().Name, $"Serial port {_portName} has been closed.");
            }

            if (read > 0 || count == 0)
            {
                return read;
            }

            // The long read timeout expired with nothing received: issue the read again.
            ThrowIfDisposed();
            cancellationToken.ThrowIfCancellationRequested();
        }
    }

    public override void Write(byte[] buffer, int offset, int count)
    {
        ThrowIfDisposed();
        _file.Write(buffer, offset, count);
    }

    public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
    {
        ThrowIfDisposed();
        return _file.WriteAsync(buffer, offset, count, cancellationToken);
    }

#if NET
    public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
    {
        ThrowIfDisposed();
        while (true)
        {
            int read;
            try
            {
                read = await _file.ReadAsync(buffer, cancellationToken).ConfigureAwait(false);
            }
            catch (Exception ex) when (Volatile.Read(ref _disposed) != 0 && ex is not OperationCanceledException)
            {
                throw new ObjectDisposedException(GetType().Name, $"Serial port {_portName} has been closed.");
            }

            if (read > 0 || buffer.IsEmpty)
            {
                return read;
            }

            ThrowIfDisposed();
            cancellationToken.ThrowIfCancellationRequested();
        }
    }

    public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
    {
        ThrowIfDisposed();
        return _file.WriteAsync(buffer, cancellationToken);
    }
#endif

    private void ThrowIfDisposed()
    {
        if (Volatile.Read(ref _disposed) != 0)
        {
            throw new ObjectDisposedException(GetType().Name, $"Serial port {_portName} has been closed.");
        }
    }

    protected override void Dispose(bool disposing)
    {
        if (Interlocked.Exchange(ref _disposed, 1) == 0 && disposing)
        {
            // Closing the handle completes any pending overlapped read or write.
            _file.Dispose();
            _handle.Dispose();
        }

        base.Dispose(disposing);
    }
}
