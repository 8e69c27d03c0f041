namespace OmronHostLink.Transports;

/// <summary>
/// A serial port (RS-232C, RS-422A/485 adapter, USB serial) on System.IO.Ports. Opened on first use; after the port is
/// lost (a USB adapter unplugged) the next exchange opens it again.
/// </summary>
/// <remarks>
/// <para>Only the port's <c>BaseStream</c> carries data: the link reads it through its own pump and never cancels a
/// read, so deadlines hold although a read on Windows ignores its cancellation token; closing the transport closes the
/// port, which ends a pending read.</para>
/// <para>A pseudo-terminal (<c>/dev/pts/N</c>, or a link to one such as socat's <c>link=/tmp/ttyV0</c>) is opened with
/// the 8 data bits and no parity it holds, whatever <see cref="SerialLineSettings"/> asks: a pty has no line, and some
/// kernels refuse to change its framing after its first user closed it. Deadlines are still timed from the configured
/// settings.</para>
/// </remarks>
public sealed class SerialTransport : IHostLinkTransport, IDisposable
{
    private readonly SerialLineSettings _settings;
    private readonly Func<SerialLineSettings, ISerialPort> _createPort;
    private SerialLineStream? _stream;

    /// <summary>Creates the transport; the settings are checked now and the port opens on first use.</summary>
    /// <param name="settings">The port and its line settings; a copy is kept, so later changes have no effect.</param>
    /// <exception cref="ArgumentException">A setting is not valid.</exception>
    public SerialTransport(SerialLineSettings settings)
        : this(settings, SystemSerialPort.Create)
    {
    }

    /// <summary>Creates the transport over ports made by <paramref name="createPort"/> (tests stand in for the operating system with it).</summary>
    internal SerialTransport(SerialLineSettings settings, Func<SerialLineSettings, ISerialPort> createPort)
    {
        Guard.NotNull(settings);
        settings.Validate();
        _settings = settings.Clone();
        _createPort = createPort;
        LineTiming = new LineTiming(settings.BaudRate, settings.BitsPerCharacter);
    }

    /// <inheritdoc/>
    public string Description => _settings.ToString();

    /// <summary>The port's name alone (the link's default name in metrics and traces).</summary>
    internal string PortName => _settings.PortName;

    /// <inheritdoc/>
    public LineTiming? LineTiming { get; }

    /// <summary>True when the open port is a pseudo-terminal, opened with its own 8-bit framing (see the remarks).</summary>
    internal bool IsPseudoTerminal { get; private set; }

    /// <inheritdoc/>
    public ValueTask<Stream> OpenAsync(CancellationToken cancellationToken)
    {
        cancellationToken.ThrowIfCancellationRequested();
        _stream ??= Open();
        return new ValueTask<Stream>(_stream);
    }

    /// <inheritdoc/>
    public ValueTask CloseAsync()
    {
        Dispose();
        return default;
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => CloseAsync();

    /// <summary>Closes the port at once; the next open opens it again.</summary>
    public void Dispose() => Interlocked.Exchange(ref _stream, null)?.Dispose();

    private SerialLineStream Open()
    {
        ISerialPort port;
        try
        {
            port = _createPort(_settings);
        }
        catch (Exception e) when (SerialOpenFailure.Is(e))
        {
            throw SerialOpenFailure.Describe(_settings, e, SerialOpenFailure.Stage.Open);
        }

        SerialOpenFailure.Stage stage = SerialOpenFailure.Stage.Open;
        try
        {
            port.Open();
            if (_settings.DtrEnable)
            {
                stage = SerialOpenFailure.Stage.RaiseDtr;
                port.SetDtr(true);
            }

            if (_settings.RtsEnable)
            {
                stage = SerialOpenFailure.Stage.RaiseRts;
                port.SetRts(true);
            }

            IsPseudoTerminal = port.IsPseudoTerminal;
            return new SerialLineStream(port);
        }
        catch (Exception e) when (SerialOpenFailure.Is(e))
        {
            port.Dispose();
            throw SerialOpenFailure.Describe(_settings, e, stage);
        }
    }
}
