namespace OmronHostLink.Link;

/// <summary>The frames of every attempt at one command, for its span.</summary>
internal sealed class FrameTally
{
    public int Sent { get; private set; }

    public int Received { get; private set; }

    public void Add(TransactionAttempt attempt)
    {
        Sent += attempt.FramesSent;
        Received += attempt.FramesReceived;
    }
}
