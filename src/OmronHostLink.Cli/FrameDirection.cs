using System.Text;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli;

/// <summary>
/// Which way a first frame goes when the user of <c>explain</c> did not say, told from its shape with the library's
/// command and answer parsers.
/// </summary>
internal static class FrameDirection
{
    /// <summary>
    /// Tells an answer from a command by its shape, for a first frame typed without <c>--response</c> or
    /// <c>--command</c>. A frame that is a well-formed answer and not a well-formed command is an answer; one that is
    /// both (<c>@00SC0050*</c>: SC to PROGRAM, and SC's normal completion; a TS echo) is ambiguous and explained as a
    /// command; one that is neither is explained as a command.
    /// </summary>
    public static void Recognise(FrameExplanation x, string header, ReadOnlySpan<byte> text, CModeCommandTable table)
    {
        bool fins = header == CModeCommands.Fins.Header;
        string? commandFault = fins ? FinsCommandFault(text) : CModeCommandFault(header, text, x.Final, table);
        bool answer = fins ? IsFinsAnswer(text, x.Final) : IsCModeAnswer(header, text, x.Final, table);
        if (answer && commandFault is not null)
        {
            x.IsResponse = true;
            x.DirectionFrom = FrameExplanation.FromShape;
            x.Notes.Add($"Recognised as an answer by its shape: as a command, {commandFault}. Give --command to explain it as a command.");
        }
        else if (answer)
        {
            x.DirectionFrom = FrameExplanation.FromAmbiguous;
            int sub = table.Find(Encoding.ASCII.GetBytes(header), text)?.SubHeaderLength ?? 0;
            string answerIs = header == CModeCommands.Test.Header ? "the PLC's echo of it" : $"an answer with end code {Encoding.ASCII.GetString(text.Slice(sub, CModeResponse.EndCodeLength))}";
            x.Notes.Add($"This frame is ambiguous: the same characters are a well-formed {header} command and {answerIs}. Explained as a command; give --response to explain it as the answer.");
        }
        else if (commandFault is null)
        {
            x.DirectionFrom = FrameExplanation.FromShape;
        }
        else
        {
            x.Notes.Add("Neither a well-formed command nor a well-formed answer: explained as a command; give --response to explain it as an answer.");
        }
    }

    /// <summary>Why the frame is not a command a PLC would take, or null when it is one (or may be the first frame of a divided command).</summary>
    private static string? CModeCommandFault(string header, ReadOnlySpan<byte> text, bool final, CModeCommandTable table)
    {
        byte[] h = Encoding.ASCII.GetBytes(header);
        if (!final)
        {
            // Only commands whose rows allow it (writes, QQMR) are divided into frames by the host.
            return table.Find(h, text) is { MultiFrameCommand: true } ? null : $"{header} is never divided into frames by the host";
        }

        try
        {
            CModeCommandParser.Parse(table, h, text);
            return null;
        }
        catch (CModeCommandRejectedException e)
        {
            return $"a PLC would refuse it with end code {e.EndCode.ToCode()} ({e.Message.TrimEnd('.')})";
        }
    }

    /// <summary>
    /// Whether the frame is a well-formed C-mode answer: an end code the manuals define (after the sub-header of a
    /// command that has one), no data after an error end code, and data of the shape the row's answer has (checked with
    /// the same decoders as <c>--response</c>).
    /// </summary>
    internal static bool IsCModeAnswer(string header, ReadOnlySpan<byte> text, bool final, CModeCommandTable table)
    {
        if (header == CModeCommands.Test.Header || header == CModeCommands.Txd.Header)
        {
            // TS: the echo, single-frame like the command. EX: the PLC's text.
            return final;
        }

        if (header == CModeCommands.UndefinedCommand.Header)
        {
            return final && text.IsEmpty;
        }

        CModeCommandRow? row = table.Find(Encoding.ASCII.GetBytes(header), text);
        if (row is null || !row.IsExecutable || !row.ExpectsAnswer || !row.AnswerHasEndCode)
        {
            return false;
        }

        ReadOnlySpan<byte> afterSub = text[row.SubHeaderLength..];
        if (afterSub.Length < CModeResponse.EndCodeLength
            || !EndCodes.TryParse(afterSub[..CModeResponse.EndCodeLength], out EndCode code)
            || code == EndCode.UndefinedHeader
            || !EndCodes.IsDefined(code))
        {
            return false;
        }

        ReadOnlySpan<byte> data = afterSub[CModeResponse.EndCodeLength..];
        if (code != EndCode.NormalCompletion || row.DescribeAnswer is null)
        {
            // Error answers, and the answers to writes, SC and the force commands, end with the end code.
            return final && data.IsEmpty;
        }

        var scratch = new FrameExplanation { Frame = string.Empty, Final = final };
        try
        {
            FrameExplainer.DecodeData(scratch, row, data);
        }
        catch (HostLinkFrameException)
        {
            return false;
        }

        return scratch.Problems.Count == 0;
    }

    /// <summary>Why the text is not an FA command, or null when it is one.</summary>
    private static string? FinsCommandFault(ReadOnlySpan<byte> text)
    {
        try
        {
            FinsMessage.ParseCommand(text, 0);
            return null;
        }
        catch (HostLinkFrameException e)
        {
            return $"it is malformed ({FrameExplainer.Sentence(e).TrimEnd('.')})";
        }
    }

    /// <summary>Whether the text is an FA answer: a Host Link end code alone, or 00 and a FINS part whose ICF marks a response.</summary>
    internal static bool IsFinsAnswer(ReadOnlySpan<byte> text, bool final)
    {
        if (!final
            || text.Length < CModeResponse.EndCodeLength
            || !EndCodes.TryParse(text[..CModeResponse.EndCodeLength], out EndCode code)
            || code == EndCode.UndefinedHeader
            || !EndCodes.IsDefined(code))
        {
            return false;
        }

        if (code != EndCode.NormalCompletion)
        {
            return text.Length == CModeResponse.EndCodeLength;
        }

        try
        {
            FinsResponse.Parse(text, 0);
            return true;
        }
        catch (HostLinkException)
        {
            return false;
        }
    }
}
