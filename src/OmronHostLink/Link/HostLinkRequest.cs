using OmronHostLink.Protocol;

namespace OmronHostLink.Link;

/// <summary>One command for the link to carry: its unframed message and how the command says it travels and is answered.</summary>
internal readonly struct HostLinkRequest
{
    public HostLinkRequest(int unit, string header, ReadOnlyMemory<byte> message, ExchangeShape shape)
    {
        Unit = unit;
        Header = header;
        Message = message;
        Shape = shape;
    }

    public int Unit { get; }

    /// <summary>The two header characters the answer must echo.</summary>
    public string Header { get; }

    /// <summary><c>@</c> + unit + header + text, unframed.</summary>
    public ReadOnlyMemory<byte> Message { get; }

    /// <summary>How the command travels and is answered.</summary>
    public ExchangeShape Shape { get; }

    /// <summary>Whether the command only reads (<see cref="CommandEffect.ReadOnly"/>): the link may send it again to confirm its answer.</summary>
    public bool ReadOnly { get; init; }

    /// <summary>Refuses, before anything is sent, a command that cannot travel in multiple frames and does not fit one.</summary>
    /// <exception cref="ArgumentException">The command is longer than one frame can carry.</exception>
    public void CheckLength()
    {
        if (!Shape.MultiFrameCommand && !Shape.SingleFrameOnly && Message.Length + FrameWriter.FinalOverhead > FrameWriter.MaxFirstFrameLength)
        {
            throw new ArgumentException($"The {Header} command is {Message.Length + FrameWriter.FinalOverhead} characters long; it must fit one {FrameWriter.MaxFirstFrameLength}-character frame.");
        }
    }
}
