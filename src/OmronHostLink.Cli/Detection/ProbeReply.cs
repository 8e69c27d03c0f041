using System.Globalization;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Cli.Detection;

/// <summary>
/// What came back after one TS probe, sorted the way a diagnosis needs it: copies of our own frame (a PLC's TS answer
/// is the same characters, and so is a 2-wire line's echo), an answer carrying an end code, an IC answer, frames whose
/// FCS does not match, and bytes that do not frame at all.
/// </summary>
internal sealed class ProbeReply
{
    private ProbeReply(byte[] bytes)
    {
        Bytes = bytes;
    }

    /// <summary>Everything received, in order.</summary>
    public byte[] Bytes { get; }

    /// <summary>How many times our own frame came back, character for character.</summary>
    public int Copies { get; private set; }

    /// <summary>The end code of a TS answer that carries one (<c>@00TS13…</c>: the PLC took the frame but found a fault), or null.</summary>
    public string? EndCode { get; private set; }

    /// <summary>Whether an IC answer came: the port took the frame but not the command.</summary>
    public bool Ic { get; private set; }

    /// <summary>Frames (from <c>@</c> to CR, printable) whose FCS does not match their characters.</summary>
    public int BadFcs { get; private set; }

    /// <summary>Sound frames that are none of the above (another unit's traffic, an EX frame).</summary>
    public int OtherFrames { get; private set; }

    /// <summary>Bytes outside any frame: before <c>@</c>, unprintable, or a run without its CR.</summary>
    public int Unframed { get; private set; }

    /// <summary>Whether nothing at all came back.</summary>
    public bool Silent => Bytes.Length == 0;

    /// <summary>Whether a unit answered in a way that shows the line's settings are right: our frame back, an end code or IC.</summary>
    public bool Answered(bool echo) => Copies >= (echo ? 2 : 1) || EndCode is not null || Ic;

    /// <summary>Sorts <paramref name="received"/>, the bytes that came back after <paramref name="sent"/>.</summary>
    public static ProbeReply Of(ReadOnlySpan<byte> sent, ReadOnlySpan<byte> received)
    {
        var reply = new ProbeReply(received.ToArray());
        ReadOnlySpan<byte> rest = received;
        while (!rest.IsEmpty)
        {
            int cr = rest.IndexOf((byte)'\r');
            if (cr < 0)
            {
                reply.Unframed += rest.Length;
                break;
            }

            ReadOnlySpan<byte> segment = rest.Slice(0, cr + 1);
            rest = rest.Slice(cr + 1);
            int at = segment.LastIndexOf((byte)'@');
            if (at < 0)
            {
                reply.Unframed += segment.Length;
                continue;
            }

            reply.Unframed += at;
            reply.Take(sent, segment.Slice(at));
        }

        return reply;
    }

    /// <summary>The bytes in a form fit for a message: printable, at most <paramref name="limit"/> of them.</summary>
    public string Sample(int limit = 24)
        => Bytes.Length <= limit ? FrameText.Printable(Bytes) : FrameText.Printable(Bytes.AsSpan(0, limit)) + "…";

    private void Take(ReadOnlySpan<byte> sent, ReadOnlySpan<byte> frame)
    {
        if (frame.SequenceEqual(sent))
        {
            Copies++;
            return;
        }

        FrameCheck check = FrameCheck.Of(frame);
        if (check.ShapeFault(frame) is not null || check.FirstFrameFault(frame) is not null)
        {
            Unframed += frame.Length;
            return;
        }

        if (!check.FcsMatches)
        {
            BadFcs++;
            return;
        }

        ReadOnlySpan<byte> header = frame.Slice(3, 2);
        int textLength = check.FirstFrameTextLength;
        if (CModeHeaders.Is(header, CModeCommands.UndefinedCommand.Header) && textLength == 0)
        {
            Ic = true;
        }
        else if (CModeHeaders.Is(header, CModeCommands.Test.Header) && textLength == 2 && HexAscii.TryParseByte(frame.Slice(5, 2), out byte code))
        {
            EndCode = code.ToString("X2", CultureInfo.InvariantCulture);
        }
        else
        {
            OtherFrames++;
        }
    }
}
