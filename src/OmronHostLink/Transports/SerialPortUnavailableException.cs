namespace OmronHostLink.Transports;

/// <summary>
/// A serial port could not be opened or configured: it does not exist, is in use, is not a serial device,
/// the user lacks permission, or it refused the requested line settings.
/// </summary>
/// <remarks>The message names the port and the reason, for example
/// "Cannot open serial port /dev/ttyUSB9: no such device (ENOENT)".</remarks>
public sealed class SerialPortUnavailableException : IOException
{
    /// <summary>Creates the exception for <paramref name="portName"/> with a short, human-readable <paramref name="reason"/>.</summary>
    /// <param name="portName">The port as the user named it (COM3, /dev/ttyUSB0, /tmp/ttyV0).</param>
    /// <param name="reason">Why it is unavailable, e.g. "no such device (ENOENT)".</param>
    public SerialPortUnavailableException(string portName, string reason)
        : this(portName, reason, 0, null)
    {
    }

    /// <summary>Creates the exception with the operating system's error code and an optional inner exception.</summary>
    /// <param name="portName">The port as the user named it.</param>
    /// <param name="reason">Why it is unavailable.</param>
    /// <param name="nativeErrorCode">The <c>errno</c> value on Unix or the Win32 error code on Windows; 0 when there is none.</param>
    /// <param name="innerException">The underlying exception, if any.</param>
    public SerialPortUnavailableException(string portName, string reason, int nativeErrorCode, Exception? innerException)
        : base($"Cannot open serial port {portName}: {reason}", innerException)
    {
        PortName = portName;
        Reason = reason;
        NativeErrorCode = nativeErrorCode;
    }

    /// <summary>The port as the user named it.</summary>
    public string PortName { get; }

    /// <summary>Why the port is unavailable, without the port name.</summary>
    public string Reason { get; }

    /// <summary>The <c>errno</c> value on Unix or the Win32 error code on Windows; 0 when there is none.</summary>
    public int NativeErrorCode { get; }
}
