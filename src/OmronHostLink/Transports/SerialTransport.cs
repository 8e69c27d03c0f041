namespace OmronHostLink.Transports;

/// <summary>
/// A serial port (RS-232C, RS-422A/485 adapter, USB serial). Opened on first use; after the port is lost (a USB
/// adapter unplugged) the next exchange opens it again.
/// </summary>
public sealed class SerialTransport : IHostLinkTransport
{
    private readonly SerialLineSettings _settings;
    private Stream? _stream;

    /// <summary>Creates the transport; the settings are checked now and the port opens on first use.</summary>
    /// <exception cref="ArgumentException">A setting is not valid.</exception>
    public SerialTransport(SerialLineSettings settings)
    {
        Guard.NotNull(settings);
        settings.Validate();
        _settings = settings;
        LineTiming = new LineTiming(settings.BaudRate, settings.BitsPerCharacter);
    }

    /// <inheritdoc/>
    public string Description => _settings.ToString();

    /// <inheritdoc/>
    public LineTiming? LineTiming { get; }

    /// <inheritdoc/>
    public ValueTask<Stream> OpenAsync(CancellationToken cancellationToken)
    {
        if (_stream is not null)
        {
            return new ValueTask<Stream>(_stream);
        }

        try
        {
            _stream = SerialPortStream.Open(_settings);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or PlatformNotSupportedException)
        {
            throw new HostLinkConnectionException(e is SerialPortUnavailableException ? e.Message + "." : $"Cannot open serial port {_settings.PortName}: {e.Message}", e);
        }

        return new ValueTask<Stream>(_stream);
    }

    /// <inheritdoc/>
    public async ValueTask CloseAsync()
    {
        Stream? s = _stream;
        _stream = null;
        if (s is not null)
        {
            await StreamCompat.DisposeAsync(s).ConfigureAwait(false);
        }
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => CloseAsync();
}
