using System.Globalization;
using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli;

/// <summary>
/// Decodes captured frames without a PLC, with the library's own parsers: <see cref="FrameCheck"/> for shape, FCS and
/// unit, <see cref="CModeCommandTable"/> for header names, <see cref="CModeCommand.Parse"/> and <see cref="CModeResponse"/>
/// for C-mode fields, <see cref="FinsMessage"/> and <see cref="FinsResponse"/> for FINS (parameters and answer data from
/// the rows of <see cref="FinsCommandTable"/>). Without a direction from the user, <see cref="FrameDirection"/> tells it.
/// </summary>
internal static class FrameExplainer
{
    /// <summary>Turns what the user typed into frame bytes: a literal <c>\r</c> becomes CR; surrounding whitespace and a trailing LF go.</summary>
    public static byte[] Normalise(string input)
    {
        string s = input.Replace("\\r", "\r", StringComparison.Ordinal).Replace("\\n", "\n", StringComparison.Ordinal);
        s = s.Trim(' ', '\t', '\n');
        var bytes = new byte[s.Length];
        for (int i = 0; i < s.Length; i++)
        {
            if (s[i] > 0x7E && s[i] != '\r')
            {
                throw new UsageException($"The frame holds the non-ASCII character '{s[i]}' at position {i}; a Host Link frame is ASCII.");
            }

            bytes[i] = (byte)s[i];
        }

        if (bytes.Length == 0)
        {
            throw new UsageException("The frame is empty.");
        }

        return bytes;
    }

    /// <summary>Explains one frame with the standard command table.</summary>
    /// <param name="input">The frame as the user typed it.</param>
    /// <param name="response">True for an answer, false for a command, null to tell from the frame where it can.</param>
    public static FrameExplanation Explain(string input, bool? response) => Explain(input, response, CModeCommandTable.Standard);

    /// <summary>Explains one frame, looking C-mode headers up in <paramref name="table"/> and FINS codes in <paramref name="fins"/> (default: the standard FINS table).</summary>
    internal static FrameExplanation Explain(string input, bool? response, CModeCommandTable table, FinsCommandTable? fins = null)
    {
        fins ??= FinsCommandTable.Standard;
        byte[] typed = Normalise(input);
        var x = new FrameExplanation
        {
            Frame = FrameText.Printable(typed),
            IsResponse = response ?? false,
            DirectionFrom = response is null ? FrameExplanation.FromDefault : FrameExplanation.FromOption,
        };
        if (typed.AsSpan().SequenceEqual(CModeFrames.Initialize) || typed.AsSpan().SequenceEqual(CModeFrames.Initialize[..^1]))
        {
            if (response is null)
            {
                x.DirectionFrom = FrameExplanation.FromShape;
            }

            x.Header = CModeCommands.Initialize.Header;
            x.Name = CModeCommands.Initialize.Name;
            x.Notes.Add("INITIALIZE carries no unit number and no FCS; no unit answers it.");
            return x;
        }

        byte[] frame = WithEnding(x, typed);
        FrameCheck check = FrameCheck.Of(frame);
        x.Final = check.IsFinal;
        if (check.ShapeFault(frame) is { } shape)
        {
            x.Problems.Add(shape);
            return x;
        }

        x.FcsExpected = check.ExpectedFcs.ToString("X2", CultureInfo.InvariantCulture);
        x.FcsFound = Encoding.ASCII.GetString(frame, check.FcsAt, 2);
        if (FcsFault(check, frame, x.FcsFound) is { } fcs)
        {
            x.Problems.Add(fcs);
        }

        if (!check.IsFirst)
        {
            x.Text = Encoding.ASCII.GetString(frame, 0, check.FcsAt);
            x.Notes.Add("No '@': a continuation frame (its FCS covers this frame only); unit and header are in the first frame.");
            if (response is null)
            {
                x.Notes.Add("A continuation frame does not show which way it goes: explained as a frame of a command; give --response for a frame of an answer.");
            }

            CheckLength(x, frame.Length, first: false, fins: false);
            return x;
        }

        if (check.FirstFrameFault(frame) is { } start)
        {
            x.Problems.Add(start);
            return x;
        }

        x.Unit = check.Unit;
        if (SettingRules.UnitNumber(check.Unit) is { } problem)
        {
            x.Notes.Add($"Unit {problem}: Host Link does not address it.");
        }

        string header = Encoding.ASCII.GetString(frame, 3, 2);
        ReadOnlySpan<byte> text = frame.AsSpan(MessagePrefix.Length, check.FirstFrameTextLength);
        x.Header = header;
        x.Name = table.Name(header, text);
        x.Text = Encoding.ASCII.GetString(text);
        if (response is null)
        {
            FrameDirection.Recognise(x, header, text, table);
        }

        CheckLength(x, frame.Length, first: true, fins: header == CModeCommands.Fins.Header);
        switch ((header == CModeCommands.Fins.Header, x.IsResponse))
        {
            case (true, true):
                ExplainFinsResponse(x, text, check.Unit, fins);
                break;
            case (true, false):
                ExplainFinsCommand(x, text, check.Unit, fins);
                break;
            case (false, true):
                ExplainResponse(x, header, text, table);
                break;
            default:
                ExplainCommand(x, header, text, table);
                break;
        }

        return x;
    }

    /// <summary>
    /// A frame longer than Host Link allows: a PLC answers end code 18 to a first or single C-mode frame over 131
    /// characters and A8 to a later frame over 128 (the FCS, <c>*</c> and CR counted), and never sends one itself.
    /// An FA frame is never divided and may hold up to 1,115 characters.
    /// </summary>
    private static void CheckLength(FrameExplanation x, int length, bool first, bool fins)
    {
        int limit = fins ? FinsMessage.MaxFrameLength : first ? FrameWriter.MaxFirstFrameLength : FrameWriter.MaxContinuationFrameLength;
        if (length <= limit)
        {
            return;
        }

        string frame = fins ? "an FA frame" : first ? "a frame" : "a later frame of a divided message";
        string characters = $"The frame is {length} characters long (FCS, '*' and CR counted)";
        if (x.IsResponse)
        {
            x.Problems.Insert(0, $"{characters}; a PLC never sends {frame} over {limit} characters (it divides a longer answer into frames).");
            return;
        }

        if (fins)
        {
            x.Problems.Insert(0, $"{characters}; {frame} holds at most {limit}.");
            return;
        }

        EndCode code = first ? EndCode.FrameLengthError : EndCode.AbortedFrameLengthError;
        string name = first ? "frame length error" : "aborted: frame length error in a later frame";
        WouldAnswer(x, code);
        x.Problems.Insert(0, $"{characters}: a PLC answers end code {code.ToCode()} ({name}) to {frame} over {limit} characters.");
    }

    /// <summary>The exception's sentence without the frame it quotes (the explanation shows the frame).</summary>
    internal static string Sentence(HostLinkFrameException e)
        => e.Frame is { } frame && e.Message.EndsWith($" Frame: {frame}", StringComparison.Ordinal)
            ? e.Message[..^($" Frame: {frame}".Length)]
            : e.Message;

    /// <summary>Records the end code a CS/CJ would answer; the first error a PLC detects is the one it answers.</summary>
    private static bool WouldAnswer(FrameExplanation x, EndCode code)
    {
        if (x.Fields.ContainsKey("wouldAnswer"))
        {
            return false;
        }

        x.Field("wouldAnswer", code.ToCode());
        x.Field("wouldAnswerMeaning", code.Meaning());
        return true;
    }

    /// <summary>
    /// The FCS problem, if any. An FCS that is right but in lower case is named as such: Omron sends it in upper case
    /// and the library's link compares it character for character, so it refuses one as it refuses any changed character.
    /// </summary>
    private static string? FcsFault(FrameCheck check, byte[] frame, string found)
    {
        string expected = check.ExpectedFcs.ToString("X2", CultureInfo.InvariantCulture);
        return FrameExplanation.IsLowercaseOf(found, expected)
            ? $"FCS '{found}' is a lowercase FCS: the right value, in lower case. Host Link sends the FCS in upper case ('{expected}'); this library's link refuses a lowercase FCS as it refuses any changed character."
            : check.FcsFault(frame);
    }

    /// <summary>The frame with its ending: a frame typed without <c>*</c> or CR is read as a complete (final) frame.</summary>
    private static byte[] WithEnding(FrameExplanation x, byte[] typed)
    {
        bool cr = typed[^1] == (byte)'\r';
        int end = cr ? typed.Length - 1 : typed.Length;
        bool star = end > 0 && typed[end - 1] == (byte)'*';
        if (cr)
        {
            if (!star)
            {
                x.Notes.Add("Ends with CR without '*': a non-final frame of a multi-frame exchange (the other side answers a bare CR).");
            }

            return typed;
        }

        if (!star)
        {
            x.Notes.Add("No '*' or CR at the end: read as a complete (final) frame.");
        }

        return [.. typed, .. star ? "\r"u8 : "*\r"u8];
    }

    private static void ExplainCommand(FrameExplanation x, string header, ReadOnlySpan<byte> text, CModeCommandTable table)
    {
        if (!x.Final)
        {
            x.Notes.Add("Only the first frame of the command: its fields are decoded from the text it carries.");
        }

        CModeCommand command;
        try
        {
            command = CModeCommandParser.Parse(table, Encoding.ASCII.GetBytes(header), text);
        }
        catch (CModeCommandRejectedException) when (!x.Final)
        {
            x.Notes.Add("The fields cannot be decoded from this frame alone.");
            return;
        }
        catch (CModeCommandRejectedException e)
        {
            x.Notes.Add(WouldAnswer(x, e.EndCode)
                ? $"A CS/CJ PLC would refuse this command with end code {e.EndCode.ToCode()}: {e.Message}"
                : $"Within the length a PLC takes, it would still refuse this command with end code {e.EndCode.ToCode()}: {e.Message}");
            return;
        }

        command.Row.DescribeCommand?.Invoke(command, x);
    }

    private static void ExplainResponse(FrameExplanation x, string header, ReadOnlySpan<byte> text, CModeCommandTable table)
    {
        if (header == CModeCommands.Test.Header)
        {
            x.Data = x.Text;
            x.Field("echo", x.Text);
            x.Notes.Add("A TS answer carries no end code: success is the text echoed unchanged.");
            return;
        }

        if (header == CModeCommands.UndefinedCommand.Header)
        {
            x.EndCodeMeaning = EndCode.UndefinedHeader.Meaning();
            if (text.Length != 0)
            {
                x.Problems.Add("An IC answer carries no text.");
            }

            return;
        }

        if (header == CModeCommands.Txd.Header)
        {
            x.Data = x.Text;
            x.Field("message", x.Text);
            x.Notes.Add("EX is sent by the PLC (TXD in Host Link mode) and carries no end code.");
            return;
        }

        // A command with a sub-header (QQMR, QQIR) has it echoed before the end code.
        CModeCommandRow? row = table.Find(Encoding.ASCII.GetBytes(header), text);
        int sub = row?.SubHeaderLength ?? 0;
        if (!EndCodeOf(x, text[sub..], out EndCode endCode))
        {
            return;
        }

        ReadOnlySpan<byte> data = text[(sub + CModeResponse.EndCodeLength)..];
        x.Data = Encoding.ASCII.GetString(data);
        if (endCode != EndCode.NormalCompletion)
        {
            if (!data.IsEmpty)
            {
                x.Notes.Add("An error answer normally carries no data.");
            }

            return;
        }

        try
        {
            DecodeData(x, row, data);
        }
        catch (HostLinkFrameException e)
        {
            x.Problems.Add(Sentence(e));
        }
    }

    /// <summary>Decodes the data of a normal-completion C-mode answer into fields, with its row's decoder.</summary>
    /// <exception cref="HostLinkFrameException">The data does not have the shape of the header's answer.</exception>
    internal static void DecodeData(FrameExplanation x, CModeCommandRow? row, ReadOnlySpan<byte> data)
    {
        if (row?.DescribeAnswer is { } describe)
        {
            describe(data, x);
        }
        else if (!data.IsEmpty)
        {
            x.Field("data", Encoding.ASCII.GetString(data));
        }
    }

    private static void ExplainFinsCommand(FrameExplanation x, ReadOnlySpan<byte> text, int unit, FinsCommandTable table)
    {
        FinsCommandMessage message;
        try
        {
            message = FinsMessage.ParseCommand(text, unit);
        }
        catch (HostLinkFrameException e)
        {
            x.Problems.Add(Sentence(e));
            return;
        }

        x.Field("responseWaitMs", (long)message.Header.ResponseWaitTime.TotalMilliseconds);
        FinsFields(x, message.Header, message.CommandCode, table);
        x.Field("parameters", Hex(message.Parameters.Span));
        FinsCommand command;
        try
        {
            command = message.ToCommand(table);
        }
        catch (FinsFormatException e)
        {
            x.Field("wouldAnswer", e.EndCode.ToString());
            x.Field("wouldAnswerMeaning", e.EndCode.Meaning);
            x.Notes.Add($"A CS/CJ PLC would answer this command with FINS response code {e.EndCode}: {e.Message}");
            return;
        }

        command.Row.DescribeCommand?.Invoke(command, x);
    }

    private static void ExplainFinsResponse(FrameExplanation x, ReadOnlySpan<byte> text, int unit, FinsCommandTable table)
    {
        if (!EndCodeOf(x, text, out EndCode endCode))
        {
            return;
        }

        x.Data = Encoding.ASCII.GetString(text[CModeResponse.EndCodeLength..]);
        if (endCode != EndCode.NormalCompletion)
        {
            return;
        }

        FinsResponse response;
        try
        {
            response = FinsResponse.Parse(text, unit);
        }
        catch (HostLinkFrameException e)
        {
            x.Problems.Add(Sentence(e));
            return;
        }

        FinsFields(x, response.Header, response.CommandCode, table);
        x.Field("responseCode", response.EndCode.ToString());
        x.Field("responseMeaning", response.EndCode.Meaning);
        x.Field("networkRelayError", response.EndCode.NetworkRelayError);
        x.Field("fatalCpuError", response.EndCode.FatalCpuError);
        x.Field("nonFatalCpuError", response.EndCode.NonFatalCpuError);
        x.Field("data", Hex(response.Data.Span));
        if (response.EndCode.IsSuccess)
        {
            try
            {
                table.Find(response.CommandCode)?.DescribeAnswer?.Invoke(response.Data.Span, x);
            }
            catch (HostLinkFrameException e)
            {
                x.Problems.Add(Sentence(e));
            }
        }
    }

    /// <summary>The Host Link end code at the start of an answer's text, recorded; false (with the problem) when there is none.</summary>
    private static bool EndCodeOf(FrameExplanation x, ReadOnlySpan<byte> text, out EndCode endCode)
    {
        try
        {
            endCode = CModeResponse.ReadEndCode(text);
        }
        catch (HostLinkFrameException)
        {
            x.Problems.Add("The answer has no two-digit end code after the header.");
            endCode = default;
            return false;
        }

        x.EndCode = endCode.ToCode();
        x.EndCodeMeaning = endCode.Meaning();
        return true;
    }

    /// <summary>The FINS header fields (the network ones only for a network header), the command code and its name.</summary>
    private static void FinsFields(FrameExplanation x, FinsHeader h, ushort command, FinsCommandTable table)
    {
        x.Field("icf", Hex(h.Icf));
        if (h.IsNetwork)
        {
            x.Field("rsv", Hex(h.Rsv));
            x.Field("gct", Hex(h.Gct));
            x.Field("dna", Hex(h.Dna));
            x.Field("da1", Hex(h.Da1));
        }

        x.Field("da2", Hex(h.Da2));
        if (h.IsNetwork)
        {
            x.Field("sna", Hex(h.Sna));
            x.Field("sa1", Hex(h.Sa1));
        }

        x.Field("sa2", Hex(h.Sa2));
        x.Field("sid", Hex(h.Sid));
        x.Field("command", command.ToString("X4", CultureInfo.InvariantCulture));
        x.Name = table.Name(command) is { } name ? $"FINS {command:X4} {name}" : $"FINS {command:X4}";
    }

    private static string Hex(byte value) => value.ToString("X2", CultureInfo.InvariantCulture);

    private static string Hex(ReadOnlySpan<byte> bytes)
    {
        var text = new byte[bytes.Length * 2];
        FinsBytes.WriteHex(bytes, text);
        return Encoding.ASCII.GetString(text);
    }
}
