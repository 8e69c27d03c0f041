using OmronHostLink.Protocol;

namespace OmronHostLink;

/// <summary>A received frame was damaged, foreign or malformed. No data from it is ever returned.</summary>
public sealed class HostLinkFrameException : HostLinkException
{
    /// <summary>Creates the exception.</summary>
    public HostLinkFrameException(FrameError error, string message, ReadOnlySpan<byte> frame = default)
        : base(frame.IsEmpty ? message : $"{message} Frame: {FrameText.Printable(frame)}")
    {
        Error = error;
        Frame = frame.IsEmpty ? null : FrameText.Printable(frame);
    }

    /// <summary>Why the frame was refused.</summary>
    public FrameError Error { get; }

    /// <summary>The frame as received, in printable form, where there was one.</summary>
    public string? Frame { get; }

    /// <inheritdoc/>
    /// <remarks>Always true: a frame damaged or out of step on the line may arrive whole on the next attempt.</remarks>
    public override bool IsTransient => true;
}
