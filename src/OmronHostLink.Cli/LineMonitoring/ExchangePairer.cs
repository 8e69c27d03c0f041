using System.Text;
using OmronHostLink.Capture;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// Follows Host Link's exchanges through the frames heard on a line and pairs each command with its answer: a divided
/// command (the PLC's bare CR after each frame), a divided answer (the host's bare CR for each next frame), commands
/// with no answer (<c>@**</c>, XZ), and commands nobody answered. With two ports each frame's direction is known; with
/// one (a half-duplex line) a frame that comes while a command waits is its answer when it is shaped as one, judged by
/// the same parsers as <c>explain</c>.
/// </summary>
internal sealed class ExchangePairer
{
    private readonly bool _directionsKnown;
    private MonitoredExchange? _open;
    private State _state;

    /// <param name="directionsKnown">True with two ports (source 0 hears the host, 1 the PLC).</param>
    public ExchangePairer(bool directionsKnown)
    {
        _directionsKnown = directionsKnown;
    }

    private enum State
    {
        Idle,
        AwaitCommandHandshake,
        AwaitCommandContinuation,
        AwaitAnswer,
        AwaitAnswerHandshake,
        AwaitAnswerContinuation,
    }

    /// <summary>Whether the PLC speaks next: a command waits for its answer, or a divided exchange for the PLC's next frame or CR.</summary>
    public bool PlcSpeaksNext => _state is State.AwaitAnswer or State.AwaitCommandHandshake or State.AwaitAnswerContinuation;

    /// <summary>Takes the next frame heard (its <see cref="MonitoredFrame.Direction"/> is set on return) and adds the events it completes.</summary>
    public void Take(MonitoredFrame frame, List<MonitorEvent> events)
    {
        if (_directionsKnown)
        {
            frame.Direction = frame.Source == 0 ? LineDirection.ToPlc : LineDirection.FromPlc;
        }

        if (!frame.IsFrame)
        {
            events.Add(new MonitorEvent.Noise(frame));
            return;
        }

        bool fromHost = frame.Direction != LineDirection.FromPlc;
        bool fromPlc = frame.Direction != LineDirection.ToPlc;
        switch (_state)
        {
            case State.AwaitCommandHandshake when frame.IsDelimiter && fromPlc:
                _open!.AddAnswer(frame);
                _state = State.AwaitCommandContinuation;
                return;
            case State.AwaitCommandContinuation when !frame.IsFirst && !frame.IsDelimiter && fromHost:
                _open!.AddCommand(frame);
                _state = frame.IsFinal ? State.AwaitAnswer : State.AwaitCommandHandshake;
                return;
            case State.AwaitCommandHandshake or State.AwaitCommandContinuation or State.AwaitAnswer when frame.IsFirst && fromPlc && IsAnswer(frame):
                _open!.AddAnswer(frame);
                if (frame.IsFinal || !frame.Check.EndsWithCr)
                {
                    Complete(events);
                }
                else
                {
                    _state = State.AwaitAnswerHandshake;
                }

                return;
            case State.AwaitAnswerHandshake when frame.IsDelimiter && fromHost:
                _open!.AddCommand(frame);
                _state = State.AwaitAnswerContinuation;
                return;
            case State.AwaitAnswerContinuation when !frame.IsFirst && !frame.IsDelimiter && fromPlc:
                _open!.AddAnswer(frame);
                if (frame.IsFinal)
                {
                    Complete(events);
                }
                else
                {
                    _state = State.AwaitAnswerHandshake;
                }

                return;
        }

        if (frame.IsFirst && fromHost)
        {
            // A new command: whatever was open ends here.
            if (_open is not null)
            {
                Complete(events, _state is State.AwaitAnswerHandshake or State.AwaitAnswerContinuation ? ExchangeStatus.Cut : null);
            }

            Start(frame, events);
            return;
        }

        // A frame no exchange explains: an answer nobody asked for, a CR out of turn.
        if (!_directionsKnown)
        {
            frame.Direction = LineDirection.Unknown;
        }

        events.Add(new MonitorEvent.Stray(frame));
    }

    /// <summary>Ends what is open (monitoring stopped).</summary>
    public void Flush(List<MonitorEvent> events)
    {
        if (_open is not null)
        {
            Complete(events, _state is State.AwaitAnswerHandshake or State.AwaitAnswerContinuation ? ExchangeStatus.Cut : null);
        }
    }

    private void Start(MonitoredFrame frame, List<MonitorEvent> events)
    {
        frame.Direction = LineDirection.ToPlc;
        var exchange = new MonitoredExchange(frame);
        if (frame.IsInitialize || exchange.Header == CModeCommands.Abort.Header)
        {
            exchange.Close(ExchangeStatus.NoAnswerExpected);
            events.Add(new MonitorEvent.Exchanged(exchange));
            return;
        }

        _open = exchange;
        _state = frame.IsFinal || !frame.Check.EndsWithCr ? State.AwaitAnswer : State.AwaitCommandHandshake;
    }

    private void Complete(List<MonitorEvent> events, ExchangeStatus? status = null)
    {
        MonitoredExchange exchange = _open!;
        _open = null;
        _state = State.Idle;
        exchange.Close(status);
        events.Add(new MonitorEvent.Exchanged(exchange));
    }

    /// <summary>Whether a first frame heard while a command waits is its answer.</summary>
    private bool IsAnswer(MonitoredFrame frame)
    {
        MonitoredExchange open = _open!;
        if (_directionsKnown)
        {
            // From the PLC's side: the answer, whatever it says.
            return true;
        }

        if (!frame.Check.FcsMatches)
        {
            // A damaged frame where an answer is due is the answer, damaged (its unit or header may be what the damage
            // hit): a host sends its next command only after its own deadline, and sends it sound.
            return !frame.Bytes.AsSpan().SequenceEqual(open.CommandFrames[0].Bytes);
        }

        if (frame.Unit != open.Unit)
        {
            return false;
        }

        string? header = frame.Header;
        if (header == CModeCommands.UndefinedCommand.Header)
        {
            return true;
        }

        if (header != open.Header || frame.Check.FcsAt < 5)
        {
            return false;
        }

        ReadOnlySpan<byte> text = frame.Bytes.AsSpan(5, frame.Check.FcsAt - 5);
        if (header == CModeCommands.Test.Header)
        {
            // The echo of the command, or an error answer (an end code alone).
            return frame.Bytes.AsSpan().SequenceEqual(open.CommandFrames[0].Bytes) || text.Length == 2;
        }

        return header == CModeCommands.Fins.Header
            ? FrameDirection.IsFinsAnswer(text, frame.IsFinal)
            : FrameDirection.IsCModeAnswer(header, text, frame.IsFinal, CModeCommandTable.Standard);
    }

    /// <summary>The text of a frame, for messages.</summary>
    internal static string Text(MonitoredFrame frame) => Encoding.ASCII.GetString(frame.Bytes);
}
