using OmronHostLink.Capture;

namespace OmronHostLink.Link;

/// <summary>The client's trace file (the client option TraceFile, carried by <see cref="HostLinkConnectionOptions.TraceFile"/>): every frame tapped, written to a capture.</summary>
internal sealed class CaptureTap : FrameTap, IDisposable
{
    private readonly CaptureWriter _writer;

    public CaptureTap(CaptureWriter writer)
    {
        _writer = writer;
    }

    /// <summary>Creates the trace file, or says in the option's words why it cannot be.</summary>
    /// <exception cref="ArgumentException">The file cannot be created.</exception>
    public static CaptureTap Create(string path)
    {
        try
        {
            return new CaptureTap(CaptureWriter.Create(path));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new ArgumentException($"TraceFile '{path}' cannot be created: {e.Message}", nameof(HostLinkConnectionOptions.TraceFile), e);
        }
    }

    public override void OnFrame(in TappedFrame frame)
    {
        try
        {
            _writer.Write(frame.Time, frame.Direction, frame.Bytes);
        }
        catch (IOException)
        {
            // A full disk ends the trace, not the exchange it records.
        }
    }

    public void Dispose() => _writer.Dispose();
}
