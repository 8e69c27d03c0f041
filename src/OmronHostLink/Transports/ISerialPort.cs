namespace OmronHostLink.Transports;

/// <summary>
/// The little of a serial port the transport uses, so that tests can stand in for the operating system where a real
/// port cannot show a case (a port in use, permission denied, a stream that ignores cancellation as Windows does).
/// </summary>
internal interface ISerialPort : IDisposable
{
    /// <summary>The port as the user named it.</summary>
    string PortName { get; }

    /// <summary>True when the device is a pseudo-terminal and was opened with the 8-bit, no-parity framing it holds.</summary>
    bool IsPseudoTerminal { get; }

    /// <summary>The open port's byte stream.</summary>
    Stream BaseStream { get; }

    /// <summary>Opens the device and applies the line settings, with DTR and RTS off.</summary>
    /// <exception cref="UnauthorizedAccessException">Opening failed (missing, busy, no permission, not a serial device).</exception>
    /// <exception cref="IOException">The device failed or refused a setting.</exception>
    /// <exception cref="ArgumentException">The device refused the line settings.</exception>
    void Open();

    /// <summary>Raises or lowers DTR.</summary>
    /// <exception cref="IOException">The device has no modem-control lines (a pseudo-terminal).</exception>
    void SetDtr(bool on);

    /// <summary>Raises or lowers RTS.</summary>
    /// <exception cref="IOException">The device has no modem-control lines (a pseudo-terminal).</exception>
    void SetRts(bool on);
}
