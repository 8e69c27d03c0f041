using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Transports;

/// <summary>
/// Stands in for the operating system where a real port cannot show a case on this machine: it throws from
/// <see cref="Open"/> exactly what System.IO.Ports throws (the shapes are checked against real failures in
/// <see cref="SerialOpenFailureTests"/>), or hands out a given stream.
/// </summary>
internal sealed class FakeSerialPort(string portName, Stream? stream = null) : ISerialPort
{
    public Exception? OpenFails { get; init; }

    public Exception? DtrFails { get; init; }

    public string PortName { get; } = portName;

    public bool IsPseudoTerminal => false;

    public Stream BaseStream => stream ?? throw new InvalidOperationException("The port is not open.");

    public bool Disposed { get; private set; }

    public bool Dtr { get; private set; }

    public bool Rts { get; private set; }

    public void Open()
    {
        if (OpenFails is not null)
        {
            throw OpenFails;
        }
    }

    public void SetDtr(bool on) => Dtr = DtrFails is null ? on : throw DtrFails;

    public void SetRts(bool on) => Rts = on;

    public void Dispose()
    {
        Disposed = true;
        stream?.Dispose();
    }
}
