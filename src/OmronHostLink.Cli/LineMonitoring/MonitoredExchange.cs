using System.Globalization;
using System.Text;
using OmronHostLink.Capture;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>How a monitored exchange ended.</summary>
internal enum ExchangeStatus
{
    /// <summary>Answered, sound, end code 00 (or a TS echo).</summary>
    Ok,

    /// <summary>Answered with an error end code, IC, or a FINS response code other than normal completion.</summary>
    EndCode,

    /// <summary>No answer came before the next command, or before monitoring stopped.</summary>
    Unanswered,

    /// <summary>A frame of the command or of the answer has a wrong FCS or a broken shape.</summary>
    Damaged,

    /// <summary>A command that has no answer: <c>@**</c> (INITIALIZE) or XZ (ABORT).</summary>
    NoAnswerExpected,

    /// <summary>A divided answer the host cut short (XZ, <c>@**</c> or another command instead of the CR for the next frame).</summary>
    Cut,
}

/// <summary>One command and its answer as heard on the line: frames, times, unit, header, end code, latency.</summary>
internal sealed class MonitoredExchange
{
    private readonly List<MonitoredFrame> _command = new();
    private readonly List<MonitoredFrame> _answer = new();

    public MonitoredExchange(MonitoredFrame first)
    {
        _command.Add(first);
        Unit = first.Unit;
        Header = first.Header ?? "??";
    }

    /// <summary>The host's frames: the command's frames, and the bare CRs asking for each later frame of the answer.</summary>
    public IReadOnlyList<MonitoredFrame> CommandFrames => _command;

    /// <summary>The PLC's frames: the answer's frames, and the bare CRs asking for each later frame of a divided command.</summary>
    public IReadOnlyList<MonitoredFrame> AnswerFrames => _answer;

    /// <summary>Every frame of the exchange, in the order it crossed the line.</summary>
    public IEnumerable<MonitoredFrame> Frames => _command.Concat(_answer).OrderBy(f => f.LastTicks);

    public int Unit { get; }

    public string Header { get; }

    public ExchangeStatus Status { get; private set; }

    /// <summary>The answer's Host Link end code (two hex digits), <c>IC</c>, or null (a TS echo, no answer).</summary>
    public string? EndCode { get; private set; }

    /// <summary>The FINS response code of an FA answer (four hex digits), or null.</summary>
    public string? FinsCode { get; private set; }

    /// <summary>From the last byte of the command to the first byte of its answer; null when unanswered.</summary>
    public TimeSpan? Latency { get; private set; }

    /// <summary>What is wrong with its frames, one sentence each.</summary>
    public List<string> Problems { get; } = new();

    /// <summary>The first answer frame, or null.</summary>
    public MonitoredFrame? Answer { get; private set; }

    /// <summary>When the command's first byte came.</summary>
    public long StartTicks => _command[0].FirstTicks;

    public void AddCommand(MonitoredFrame frame)
    {
        frame.Direction = LineDirection.ToPlc;
        _command.Add(frame);
    }

    public void AddAnswer(MonitoredFrame frame)
    {
        frame.Direction = LineDirection.FromPlc;
        if (Answer is null && frame.IsFirst)
        {
            Answer = frame;
            MonitoredFrame lastCommand = _command.Where(f => f.LastTicks <= frame.FirstTicks).DefaultIfEmpty(_command[^1]).Last();
            Latency = MonitorClock.Between(lastCommand.LastTicks, frame.FirstTicks);
        }

        _answer.Add(frame);
    }

    /// <summary>Ends the exchange: works out its status from its frames.</summary>
    public void Close(ExchangeStatus? ended = null)
    {
        foreach (MonitoredFrame f in _command.Concat(_answer))
        {
            if (f.Fault is { } fault)
            {
                Problems.Add($"{(f.Direction == LineDirection.FromPlc ? "answer" : "command")} frame {Encoding.ASCII.GetString(f.Bytes).TrimEnd('\r')}: {fault}");
            }
        }

        if (ended is { } status)
        {
            Status = status;
            return;
        }

        if (Answer is null)
        {
            Status = ExchangeStatus.Unanswered;
            return;
        }

        ReadEndCode(Answer.Bytes);
        Status = Problems.Count > 0 ? ExchangeStatus.Damaged
            : EndCode is null || (EndCode == "00" && FinsCode is null or "0000") ? ExchangeStatus.Ok
            : ExchangeStatus.EndCode;
    }

    private void ReadEndCode(byte[] answer)
    {
        string? header = Answer!.Header;
        if (header == CModeCommands.UndefinedCommand.Header)
        {
            EndCode = "IC";
            return;
        }

        if (header == CModeCommands.Test.Header)
        {
            // TS is answered with its own text; an error answer carries the end code alone.
            int length = Answer.Check.FirstFrameTextLength;
            EndCode = length == 2 && !_command[0].Bytes.AsSpan().SequenceEqual(answer) ? Encoding.ASCII.GetString(answer, 5, 2) : null;
            return;
        }

        if (Answer.Check.FcsAt < 7)
        {
            return;
        }

        ReadOnlySpan<byte> text = answer.AsSpan(5, Answer.Check.FcsAt - 5);
        int sub = header is null ? 0 : CModeCommandTable.Standard.Find(answer.AsSpan(3, 2), text)?.SubHeaderLength ?? 0;
        if (text.Length >= sub + 2)
        {
            EndCode = Encoding.ASCII.GetString(text.Slice(sub, 2));
        }

        if (header == CModeCommands.Fins.Header && EndCode == "00")
        {
            try
            {
                FinsCode = FinsResponse.Parse(text, Unit).EndCode.ToString();
            }
            catch (HostLinkException)
            {
                // Too short or malformed: the Host Link end code is all there is.
            }
        }
    }

    /// <summary>The end code as shown: <c>00</c>, <c>00/0000</c> for FINS, <c>IC</c>, or <c>--</c>.</summary>
    public string EndCodeText => EndCode is null ? "--" : FinsCode is null ? EndCode : $"{EndCode}/{FinsCode}";

    /// <summary>Milliseconds with three decimals, invariant.</summary>
    public static string Milliseconds(TimeSpan t) => t.TotalMilliseconds.ToString("0.000", CultureInfo.InvariantCulture);
}
