using System.Text;
using OmronHostLink.Capture;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Simulator.Replay;

/// <summary>
/// The exchanges of a capture, by command: each command's frames (text without FCS and ending, an FA frame's service
/// ID left out) lead to the answers the PLC gave it, in the order it gave them.
/// </summary>
internal sealed class RecordedExchanges
{
    private readonly Dictionary<string, List<byte[][]>> _answers = new(StringComparer.Ordinal);

    private RecordedExchanges()
    {
    }

    /// <summary>How many exchanges the capture holds.</summary>
    public int Count { get; private set; }

    /// <summary>The unit numbers that answered in the capture.</summary>
    public SortedSet<int> Units { get; } = new();

    /// <summary>
    /// Cuts the capture into exchanges: a first frame from the host starts one; the host's later frames (after the PLC's
    /// CR) complete its command; the PLC's frames (and the host's CRs between them) are its answer. Records whose
    /// direction the recorder did not know, and bytes that did not frame, are left out.
    /// </summary>
    public static RecordedExchanges From(IEnumerable<CapturedFrame> frames)
    {
        var recorded = new RecordedExchanges();
        List<byte[]>? command = null;
        List<byte[]>? answer = null;
        foreach (CapturedFrame f in frames)
        {
            if (f.Direction == LineDirection.Unknown || (f.Flags & CaptureFlags.NotFramed) != 0)
            {
                continue;
            }

            bool delimiter = f.Bytes.Length == 1 && f.Bytes[0] == (byte)'\r';
            if (f.Direction == LineDirection.ToPlc)
            {
                if (delimiter)
                {
                    continue;
                }

                if (f.Bytes.Length > 0 && f.Bytes[0] == (byte)'@')
                {
                    recorded.Add(command, answer);
                    command = [f.Bytes];
                    answer = [];
                }
                else if (command is not null && answer is not null && answer.All(a => a.Length == 1 && a[0] == (byte)'\r'))
                {
                    // A later frame of a divided command (the PLC's CRs before it are handshakes).
                    command.Add(f.Bytes);
                    answer.Clear();
                }

                continue;
            }

            if (!delimiter)
            {
                answer?.Add(f.Bytes);
            }
            else if (answer is not null && answer.Count == 0)
            {
                // The PLC's CR asking for a divided command's next frame: not part of the answer.
                answer.Add(f.Bytes);
            }
        }

        recorded.Add(command, answer);
        return recorded;
    }

    /// <summary>The answers recorded for a command, in order, or null when the capture has none.</summary>
    public IReadOnlyList<byte[][]>? AnswersTo(IReadOnlyList<byte[]> command)
        => _answers.TryGetValue(Key(command), out List<byte[][]>? answers) ? answers : null;

    /// <summary>What identifies a command: its frames' texts, an FA frame's service ID left out.</summary>
    internal static string Key(IReadOnlyList<byte[]> frames)
    {
        var key = new StringBuilder();
        foreach (byte[] frame in frames)
        {
            FrameCheck check = FrameCheck.Of(frame);
            int end = check.FcsAt >= 0 ? check.FcsAt : frame.Length;
            char[] text = Encoding.ASCII.GetString(frame, 0, end).ToCharArray();
            if (key.Length == 0 && FinsServiceIdAt(frame, answer: false) is int sid)
            {
                text[sid] = '?';
                text[sid + 1] = '?';
            }

            key.Append(text).Append('|');
        }

        return key.ToString();
    }

    /// <summary>Where the two characters of an FA frame's service ID lie: after the header, the wait or end code, the ICF and the addresses.</summary>
    internal static int? FinsServiceIdAt(byte[] frame, bool answer)
    {
        if (frame.Length < 12 || frame[0] != (byte)'@' || frame[3] != (byte)'F' || frame[4] != (byte)'A')
        {
            return null;
        }

        int icfAt = 5 + (answer ? 2 : 1);
        if (!HexAscii.TryParseByte(frame.AsSpan(icfAt, 2), out byte icf))
        {
            return null;
        }

        // ICF bit 7: the network form, with RSV, GCT, DNA, DA1, DA2, SNA, SA1, SA2; else DA2 and SA2 only.
        int sid = icfAt + 2 + ((icf & 0x80) != 0 ? 16 : 4);
        return sid + 2 <= frame.Length ? sid : null;
    }

    private void Add(List<byte[]>? command, List<byte[]>? answer)
    {
        if (command is null || answer is null)
        {
            return;
        }

        answer.RemoveAll(a => a.Length == 1 && a[0] == (byte)'\r');
        if (answer.Count == 0)
        {
            return;
        }

        string key = Key(command);
        if (!_answers.TryGetValue(key, out List<byte[][]>? list))
        {
            list = new List<byte[][]>();
            _answers[key] = list;
        }

        list.Add(answer.ToArray());
        Count++;
        if (MessagePrefix.TryReadUnit(command[0], out int unit))
        {
            Units.Add(unit);
        }
    }

    /// <summary>Whether <paramref name="frame"/> is TS: answered with its own characters whatever the capture holds.</summary>
    internal static bool IsTest(byte[] frame)
        => frame.Length >= 5 && frame[0] == (byte)'@' && CModeHeaders.Is(frame.AsSpan(3, 2), CModeCommands.Test.Header);
}
