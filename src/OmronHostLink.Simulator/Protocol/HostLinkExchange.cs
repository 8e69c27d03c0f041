using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Simulator.Protocol;

/// <summary>
/// The PLC side of the Host Link frame exchange on one line: first-frame checks (unit, frame length, FCS), the
/// multi-frame command handshake (a bare CR after every non-final frame, end codes A3/A4/A5/A8 for later frames), the
/// multi-frame answer handshake (the next frame after the host's CR; XZ or <c>@**</c> abandon it; any other command
/// counts as a delimiter), and silence towards other unit numbers. Pure: no I/O, no clock.
/// </summary>
internal sealed class HostLinkExchange
{
    /// <summary>The longest text a multi-frame write may accumulate (10,000 words and the address), a guard against endless frames.</summary>
    private const int MaxCommandText = 6 + (4 * 10000);

    private readonly IReadOnlyDictionary<int, HostLinkResponder> _responders;
    private State _state;
    private int _unit;
    private byte[] _header = [];
    private CModeCommandRow? _row;
    private readonly List<byte> _text = new();
    private SimResponse? _response;
    private int _responseOffset;

    /// <summary>One PLC answering every unit number in <paramref name="units"/>.</summary>
    public HostLinkExchange(HostLinkResponder responder, IEnumerable<int> units)
        : this(units.Distinct().ToDictionary(u => u, _ => responder))
    {
    }

    /// <summary>Several PLCs on one line, each answering its own unit numbers.</summary>
    public HostLinkExchange(IReadOnlyDictionary<int, HostLinkResponder> responders)
    {
        _responders = responders;
    }

    /// <summary>The unit number of the exchange in progress, or of the last one: whose answer is being sent.</summary>
    public int Unit => _unit;

    private enum State
    {
        Idle,
        ReceivingCommand,
        SendingResponse,
    }

    /// <summary>Whether the next frame must start with <c>@</c> (no exchange is in progress), so noise before it can be skipped.</summary>
    public bool ExpectsFirstFrame => _state == State.Idle;

    /// <summary>Whether the exchange is in the middle of a multi-frame command or answer.</summary>
    public bool InProgress => _state != State.Idle;

    /// <summary>Forgets any exchange in progress (the line was reset).</summary>
    public void Reset()
    {
        _state = State.Idle;
        _row = null;
        _text.Clear();
        _response = null;
        _responseOffset = 0;
    }

    /// <summary>Handles one received frame (up to and including its CR) and returns what to send.</summary>
    public LinkReply Receive(ReadOnlySpan<byte> frame)
    {
        if (_state != State.Idle)
        {
            int at = frame.IndexOf((byte)'@');
            if (at > 0)
            {
                // Noise ahead of a new first frame.
                frame = frame.Slice(at);
            }
        }

        if (CModeFrames.IsInitialize(frame))
        {
            Reset();
            return LinkReply.None;
        }

        switch (_state)
        {
            case State.SendingResponse:
                return WhileSending(frame);
            case State.ReceivingCommand when frame.Length > 0 && frame[0] != (byte)'@':
                return Continuation(frame);
            default:
                if (_state == State.ReceivingCommand)
                {
                    // A new command interrupts the divided one.
                    Reset();
                }

                return First(frame);
        }
    }

    private LinkReply WhileSending(ReadOnlySpan<byte> frame)
    {
        if (frame.Length > 0 && frame[0] == (byte)'@')
        {
            if (!MessagePrefix.TryReadUnit(frame, out int unit) || !_responders.ContainsKey(unit))
            {
                // Another unit's traffic: not ours, and not a delimiter for us.
                return LinkReply.None;
            }

            if (frame.Length >= MessagePrefix.Length && CModeHeaders.Is(frame.Slice(3, 2), CModeCommands.Abort.Header))
            {
                Reset();
                return LinkReply.None;
            }
        }

        // The bare CR (or, per the manual, any other command) asks for the next frame.
        return NextResponseFrame();
    }

    private LinkReply NextResponseFrame()
    {
        TimeSpan delay = _responseOffset == 0 ? _response!.Delay : TimeSpan.Zero;
        byte[] frame = _response!.NextFrame(ref _responseOffset, out bool final);
        if (final)
        {
            Reset();
        }
        else
        {
            _state = State.SendingResponse;
        }

        return LinkReply.Frame(frame, delay);
    }

    private LinkReply Send(SimResponse? response)
    {
        if (response is null)
        {
            Reset();
            return LinkReply.None;
        }

        _response = response;
        _responseOffset = 0;
        return NextResponseFrame();
    }

    private LinkReply Error(ReadOnlySpan<byte> header, EndCode code)
    {
        int unit = _unit;
        string? subHeader = _row?.SubHeader;
        Reset();
        return Send(HostLinkResponder.EndCodeOnly(unit, header, code, subHeader));
    }

    private LinkReply First(ReadOnlySpan<byte> frame)
    {
        if (!MessagePrefix.TryReadUnit(frame, out int unit) || !_responders.ContainsKey(unit) || frame.Length < 6)
        {
            // Not for us, or too damaged to know whom to answer.
            return LinkReply.None;
        }

        _unit = unit;
        ReadOnlySpan<byte> header = frame.Slice(3, 2);
        int limit = CModeHeaders.Is(header, CModeCommands.Fins.Header) ? FinsMessage.MaxFrameLength : FrameWriter.MaxFirstFrameLength;
        if (frame.Length > limit)
        {
            return Error(header, EndCode.FrameLengthError);
        }

        if (Damaged(frame, first: true, out FrameInfo info) is { } damaged)
        {
            return Error(header, damaged);
        }

        ReadOnlySpan<byte> text = info.Text(frame);
        if (info.IsFinal)
        {
            return Send(_responders[unit].Respond(unit, header, text));
        }

        CModeCommandRow? row = _responders[unit].Table.Find(header, text);
        if (row is null || !row.IsExecutable || !row.MultiFrameCommand)
        {
            return Error(header, CModeHeaders.IsExecutable(header) ? EndCode.FormatError : EndCode.UndefinedHeader);
        }

        if (row.CheckFrame?.Invoke(text, first: true) is { } refused)
        {
            return Error(header, refused);
        }

        _header = header.ToArray();
        _row = row;
        _text.Clear();
        AddText(text);
        _state = State.ReceivingCommand;
        return LinkReply.Handshake;
    }

    private LinkReply Continuation(ReadOnlySpan<byte> frame)
    {
        if (frame.Length > FrameWriter.MaxContinuationFrameLength)
        {
            return Error(_header, EndCode.AbortedFrameLengthError);
        }

        if (Damaged(frame, first: false, out FrameInfo info) is { } damaged)
        {
            return Error(_header, damaged);
        }

        ReadOnlySpan<byte> text = info.Text(frame);
        if (text.Length <= 2)
        {
            // W342: two data characters or fewer in a later frame aborts with A3.
            return Error(_header, EndCode.AbortedFcsError);
        }

        if (_row?.CheckFrame?.Invoke(text, first: false) is { } refused)
        {
            return Error(_header, refused);
        }

        if (_text.Count + text.Length > MaxCommandText)
        {
            return Error(_header, EndCode.AbortedEntryNumberDataError);
        }

        AddText(text);
        if (!info.IsFinal)
        {
            return LinkReply.Handshake;
        }

        byte[] all = _text.ToArray();
        byte[] header = _header;
        int unit = _unit;
        Reset();
        return Send(_responders[unit].Respond(unit, header, all));
    }

    /// <summary>
    /// The end code a damaged frame is answered with: FCS or format error (13, 14) for a first frame, the aborted ones
    /// (A3, A4) for a later frame; null for a sound frame.
    /// </summary>
    private static EndCode? Damaged(ReadOnlySpan<byte> frame, bool first, out FrameInfo info)
    {
        try
        {
            info = first ? FrameParser.ParseFirst(frame) : FrameParser.ParseContinuation(frame);
            return null;
        }
        catch (HostLinkFrameException e)
        {
            info = default;
            bool fcs = e.Error == FrameError.BadFcs;
            return first
                ? fcs ? EndCode.FcsError : EndCode.FormatError
                : fcs ? EndCode.AbortedFcsError : EndCode.AbortedFormatError;
        }
    }

    private void AddText(ReadOnlySpan<byte> text)
    {
        foreach (byte b in text)
        {
            _text.Add(b);
        }
    }
}
