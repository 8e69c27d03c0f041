using System.Globalization;
using System.Text;
using System.Text.Json;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli;

/// <summary>A decoded frame: what <c>explain</c> prints.</summary>
internal sealed class FrameExplanation
{
    public required string Frame { get; init; }

    public required bool IsResponse { get; init; }

    public bool Valid => Problems.Count == 0;

    public int? Unit { get; set; }

    public string? Header { get; set; }

    public string? Name { get; set; }

    public string? EndCode { get; set; }

    public string? EndCodeMeaning { get; set; }

    public string? FcsExpected { get; set; }

    public string? FcsFound { get; set; }

    public bool? Final { get; set; }

    public string? Text { get; set; }

    public string? Data { get; set; }

    /// <summary>Decoded fields in order; values are string, long, bool, string[], long[], bool[] or null.</summary>
    public List<KeyValuePair<string, object?>> Fields { get; } = [];

    public List<string> Problems { get; } = [];

    public List<string> Notes { get; } = [];

    public void Field(string name, object? value) => Fields.Add(new(name, value));
}

/// <summary>Decodes captured frames without a PLC: shape, unit, header, end code, FCS and the command's or answer's fields.</summary>
internal static class FrameExplainer
{
    private static readonly Dictionary<string, string> Names = new(StringComparer.Ordinal)
    {
        ["RR"] = "CIO AREA READ", ["RL"] = "LR AREA READ", ["RH"] = "HR AREA READ", ["RC"] = "TIMER/COUNTER PV READ",
        ["RG"] = "TIMER/COUNTER STATUS READ", ["RD"] = "DM AREA READ", ["RJ"] = "AR AREA READ", ["RE"] = "EM AREA READ",
        ["WR"] = "CIO AREA WRITE", ["WL"] = "LR AREA WRITE", ["WH"] = "HR AREA WRITE", ["WC"] = "TIMER/COUNTER PV WRITE",
        ["WG"] = "TIMER/COUNTER STATUS WRITE", ["WD"] = "DM AREA WRITE", ["WJ"] = "AR AREA WRITE", ["WE"] = "EM AREA WRITE",
        ["R#"] = "SV READ 1", ["R$"] = "SV READ 2", ["R%"] = "SV READ 3", ["W#"] = "SV CHANGE 1", ["W$"] = "SV CHANGE 2", ["W%"] = "SV CHANGE 3",
        ["MS"] = "STATUS READ", ["SC"] = "STATUS CHANGE", ["MF"] = "ERROR READ", ["KS"] = "FORCED SET", ["KR"] = "FORCED RESET",
        ["FK"] = "MULTIPLE FORCED SET/RESET", ["KC"] = "FORCED SET/RESET CANCEL", ["MM"] = "PLC MODEL READ", ["TS"] = "TEST",
        ["RP"] = "PROGRAM READ", ["WP"] = "PROGRAM WRITE", ["MI"] = "I/O TABLE GENERATE", ["QQ"] = "COMPOUND COMMAND (QQMR/QQIR)",
        ["XZ"] = "ABORT", ["**"] = "INITIALIZE", ["IC"] = "UNDEFINED COMMAND (response)", ["EX"] = "TXD (PLC to host)",
        ["FA"] = "FINS COMMAND OVER HOST LINK",
    };

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

    public static FrameExplanation Explain(string input, bool response)
    {
        byte[] frame = Normalise(input);
        var x = new FrameExplanation { Frame = FrameText.Printable(frame), IsResponse = response };
        if (frame.AsSpan().SequenceEqual("@**\r"u8) || frame.AsSpan().SequenceEqual("@**"u8))
        {
            x.Header = "**";
            x.Name = Names["**"];
            x.Final = true;
            x.Notes.Add("INITIALIZE carries no unit number and no FCS; no unit answers it.");
            return x;
        }

        int end = frame.Length;
        bool hasCr = frame[end - 1] == (byte)'\r';
        if (hasCr)
        {
            end--;
        }

        bool star = end > 0 && frame[end - 1] == (byte)'*';
        if (star)
        {
            end--;
        }

        x.Final = star || !hasCr;
        if (!star && !hasCr)
        {
            x.Notes.Add("No '*' or CR at the end: read as a complete (final) frame.");
        }
        else if (!star)
        {
            x.Notes.Add("Ends with CR without '*': a non-final frame of a multi-frame exchange (the other side answers a bare CR).");
        }

        ReadOnlySpan<byte> body = frame.AsSpan(0, end);
        for (int i = 0; i < body.Length; i++)
        {
            if (body[i] is < 0x20 or > 0x7E)
            {
                x.Problems.Add($"The frame holds the control character 0x{body[i]:X2} at position {i}.");
                return x;
            }
        }

        if (body.Length < 2)
        {
            x.Problems.Add("The frame is too short to hold an FCS.");
            return x;
        }

        ReadOnlySpan<byte> checkedPart = body[..^2];
        ReadOnlySpan<byte> found = body[^2..];
        byte expected = Fcs.Compute(checkedPart);
        x.FcsExpected = expected.ToString("X2", CultureInfo.InvariantCulture);
        x.FcsFound = Encoding.ASCII.GetString(found);
        if (!Fcs.Verify(checkedPart, found, out _))
        {
            x.Problems.Add($"FCS mismatch: the frame carries '{x.FcsFound}' but its characters give '{x.FcsExpected}'.");
        }

        if (body[0] != (byte)'@')
        {
            x.Text = Encoding.ASCII.GetString(checkedPart);
            x.Notes.Add("No '@': a continuation frame (its FCS covers this frame only); unit and header are in the first frame.");
            return x;
        }

        if (checkedPart.Length < 5)
        {
            x.Problems.Add("The frame is too short to hold '@', a unit number and a header.");
            return x;
        }

        if (!HexAscii.TryParseDecimal(checkedPart.Slice(1, 2), out int unit))
        {
            x.Problems.Add($"The unit number '{Encoding.ASCII.GetString(checkedPart.Slice(1, 2))}' is not two decimal digits.");
            return x;
        }

        x.Unit = unit;
        if (unit > 31)
        {
            x.Notes.Add($"Unit {unit} is beyond 0-31, the unit numbers Host Link allows.");
        }

        string header = Encoding.ASCII.GetString(checkedPart.Slice(3, 2));
        x.Header = header;
        x.Name = Names.TryGetValue(header, out string? name) ? name : null;
        ReadOnlySpan<byte> text = checkedPart[5..];
        x.Text = Encoding.ASCII.GetString(text);
        if (header == "FA")
        {
            if (response)
            {
                ExplainFinsResponse(x, text);
            }
            else
            {
                ExplainFinsCommand(x, text);
            }
        }
        else if (response)
        {
            ExplainResponse(x, header, text);
        }
        else
        {
            ExplainCommand(x, header, text);
        }

        return x;
    }

    private static void ExplainCommand(FrameExplanation x, string header, ReadOnlySpan<byte> text)
    {
        if (x.Final == false)
        {
            x.Notes.Add("Only the first frame of the command: its fields are decoded from the text it carries.");
        }

        CModeCommand command;
        try
        {
            command = CModeCommand.Parse(Encoding.ASCII.GetBytes(header), text);
        }
        catch (CModeCommandRejectedException) when (x.Final == false)
        {
            x.Notes.Add("The fields cannot be decoded from this frame alone.");
            return;
        }
        catch (CModeCommandRejectedException e)
        {
            x.Field("wouldAnswer", e.EndCode.ToCode());
            x.Field("wouldAnswerMeaning", e.EndCode.Meaning());
            x.Notes.Add($"A CS/CJ PLC would refuse this command with end code {e.EndCode.ToCode()}: {e.Message}");
            return;
        }

        switch (command)
        {
            case AreaReadCommand r:
                x.Field("area", CModeAreaInfo.DisplayName(r.Area));
                if (r.Area == CModeArea.Em)
                {
                    x.Field("bank", (long)r.Bank);
                }

                x.Field("begin", (long)r.Begin);
                x.Field("count", (long)r.Count);
                break;
            case AreaWriteCommand w:
                x.Field("area", CModeAreaInfo.DisplayName(w.Area));
                if (w.Area == CModeArea.Em)
                {
                    x.Field("bank", (long)w.Bank);
                }

                x.Field("begin", (long)w.Begin);
                x.Field("count", (long)w.Words.Length);
                x.Field("words", Longs(w.Words));
                break;
            case StatusChangeCommand sc:
                x.Field("mode", sc.Mode.ToString().ToUpperInvariant());
                break;
            case ErrorReadCommand mf:
                x.Field("clear", mf.Clear);
                break;
            case Protocol.CMode.TestCommand ts:
                x.Field("text", ts.Text);
                break;
            case ForceBitCommand k:
                x.Field("action", k.Set ? "set" : "reset");
                x.Field("area", ForceAreaInfo.Name(k.Area).Trim());
                x.Field("word", (long)k.Word);
                x.Field("bit", (long)k.Bit);
                break;
            case MultipleForceCommand fk:
                x.Field("area", ForceAreaInfo.Name(fk.Area).Trim());
                x.Field("word", (long)fk.Word);
                x.Field("actionsBit15To0", fk.Actions.Select(a => a.ToString()).ToArray());
                break;
        }
    }

    private static void ExplainResponse(FrameExplanation x, string header, ReadOnlySpan<byte> text)
    {
        switch (header)
        {
            case "TS":
                x.Data = x.Text;
                x.Field("echo", x.Text);
                x.Notes.Add("A TS answer carries no end code: success is the text echoed unchanged.");
                return;
            case "IC":
                x.EndCodeMeaning = OmronHostLink.EndCode.UndefinedHeader.Meaning();
                if (text.Length != 0)
                {
                    x.Problems.Add("An IC answer carries no text.");
                }

                return;
            case "EX":
                x.Data = x.Text;
                x.Field("message", x.Text);
                x.Notes.Add("EX is sent by the PLC (TXD in Host Link mode) and carries no end code.");
                return;
        }

        if (text.Length < 2 || !HexAscii.TryParseByte(text[..2], out byte code))
        {
            x.Problems.Add("The answer has no two-digit end code after the header.");
            return;
        }

        var endCode = (EndCode)code;
        x.EndCode = endCode.ToCode();
        x.EndCodeMeaning = endCode.Meaning();
        ReadOnlySpan<byte> data = text[2..];
        x.Data = Encoding.ASCII.GetString(data);
        if (endCode != OmronHostLink.EndCode.NormalCompletion)
        {
            if (!data.IsEmpty)
            {
                x.Notes.Add("An error answer normally carries no data.");
            }

            return;
        }

        try
        {
            DecodeData(x, header, data);
        }
        catch (HostLinkFrameException e)
        {
            x.Problems.Add(e.Message);
        }
    }

    private static void DecodeData(FrameExplanation x, string header, ReadOnlySpan<byte> data)
    {
        switch (header)
        {
            case "RR" or "RL" or "RH" or "RC" or "RD" or "RJ" or "RE" or "R#":
                if (data.Length % 4 != 0)
                {
                    x.Problems.Add($"Read data comes in 4-digit words; {data.Length} characters is not a whole number of words.");
                    return;
                }

                var words = new ushort[data.Length / 4];
                CModeResponse.ReadWords(data, words);
                x.Field("words", Longs(words));
                if (x.Final == false)
                {
                    x.Notes.Add("More words follow in the next frames (the host asks for each with a bare CR).");
                }

                break;
            case "RG":
                var flags = new bool[data.Length];
                CModeResponse.ReadFlags(data, flags);
                x.Field("flags", flags);
                break;
            case "MS":
                PlcStatus status = CModeResponse.ReadStatus(data);
                x.Field("mode", status.Mode.ToString().ToUpperInvariant());
                x.Field("statusWord", (long)status.StatusWord);
                x.Field("userMemoryWritable", status.UserMemoryWritable);
                x.Field("message", status.Message);
                break;
            case "MF":
                PlcErrorInfo errors = CModeResponse.ReadErrors(data);
                x.Field("errorWords", new long[] { errors.FirstWord, errors.SecondWord });
                x.Field("hasErrors", errors.HasErrors);
                break;
            case "MM":
                PlcModel model = CModeResponse.ReadModel(data);
                x.Field("modelCode", model.Code.ToString("X2", CultureInfo.InvariantCulture));
                x.Field("model", model.Name);
                break;
            default:
                if (!data.IsEmpty)
                {
                    x.Field("data", Encoding.ASCII.GetString(data));
                }

                break;
        }
    }

    private static void ExplainFinsCommand(FrameExplanation x, ReadOnlySpan<byte> text)
    {
        var r = new HexFields(x, text);
        if (!r.Chars("responseWait", 1, out string wait) || !HexAscii.TryParseNibble((byte)wait[0], out int w))
        {
            r.Fail("The FINS response wait time is one hex digit.");
            return;
        }

        x.Field("responseWaitMs", (long)(w * 10));
        if (!r.Byte("icf", out byte icf))
        {
            return;
        }

        if ((icf & 0x80) != 0)
        {
            _ = r.Byte("rsv", out _) && r.Byte("gct", out _) && r.Byte("dna", out _) && r.Byte("da1", out _);
        }

        if (!r.Byte("da2", out _))
        {
            return;
        }

        if ((icf & 0x80) != 0)
        {
            _ = r.Byte("sna", out _) && r.Byte("sa1", out _);
        }

        if (!r.Byte("sa2", out _) || !r.Byte("sid", out _) || !r.Word("command", out ushort command))
        {
            return;
        }

        x.Name = $"FINS {command:X4}{FinsName(command)}";
        x.Field("parameters", r.Rest());
    }

    private static void ExplainFinsResponse(FrameExplanation x, ReadOnlySpan<byte> text)
    {
        if (text.Length < 2 || !HexAscii.TryParseByte(text[..2], out byte code))
        {
            x.Problems.Add("The answer has no two-digit Host Link end code after FA.");
            return;
        }

        var endCode = (EndCode)code;
        x.EndCode = endCode.ToCode();
        x.EndCodeMeaning = endCode.Meaning();
        x.Data = Encoding.ASCII.GetString(text[2..]);
        if (endCode != OmronHostLink.EndCode.NormalCompletion)
        {
            return;
        }

        var r = new HexFields(x, text[2..]);
        if (!r.Byte("icf", out byte icf))
        {
            return;
        }

        bool network = (icf & 0x80) != 0;
        if (network && !(r.Byte("rsv", out _) && r.Byte("gct", out _) && r.Byte("dna", out _) && r.Byte("da1", out _)))
        {
            return;
        }

        if (!r.Byte("da2", out _))
        {
            return;
        }

        if (network && !(r.Byte("sna", out _) && r.Byte("sa1", out _)))
        {
            return;
        }

        if (!r.Byte("sa2", out _) || !r.Byte("sid", out _) || !r.Word("command", out ushort command) || !r.Word("responseCode", out ushort response))
        {
            return;
        }

        var fins = new FinsEndCode(response);
        x.Name = $"FINS {command:X4}{FinsName(command)}";
        x.Field("responseMeaning", fins.Meaning);
        x.Field("networkRelayError", fins.NetworkRelayError);
        x.Field("fatalCpuError", fins.FatalCpuError);
        x.Field("nonFatalCpuError", fins.NonFatalCpuError);
        x.Field("data", r.Rest());
    }

    private static string FinsName(ushort command) => command switch
    {
        0x0101 => " MEMORY AREA READ",
        0x0102 => " MEMORY AREA WRITE",
        0x0103 => " MEMORY AREA FILL",
        0x0104 => " MULTIPLE MEMORY AREA READ",
        0x0105 => " MEMORY AREA TRANSFER",
        0x0401 => " RUN",
        0x0402 => " STOP",
        0x0501 => " CPU UNIT DATA READ",
        0x0601 => " CPU UNIT STATUS READ",
        0x0620 => " CYCLE TIME READ",
        0x0701 => " CLOCK READ",
        0x0702 => " CLOCK WRITE",
        0x2101 => " ERROR CLEAR",
        0x2102 => " ERROR LOG READ",
        0x2301 => " FORCED SET/RESET",
        0x2302 => " FORCED SET/RESET CANCEL",
        _ => string.Empty,
    };

    private static long[] Longs(ReadOnlySpan<ushort> words)
    {
        var result = new long[words.Length];
        for (int i = 0; i < words.Length; i++)
        {
            result[i] = words[i];
        }

        return result;
    }

    /// <summary>Prints the explanation for people.</summary>
    public static void WriteHuman(TextWriter w, FrameExplanation x)
    {
        w.WriteLine($"Frame:      {x.Frame}");
        w.WriteLine($"Direction:  {(x.IsResponse ? "response (PLC to host)" : "command (host to PLC)")}");
        if (x.Unit is { } unit)
        {
            w.WriteLine($"Unit:       {unit:D2}");
        }

        if (x.Header is not null)
        {
            w.WriteLine($"Header:     {x.Header}{(x.Name is null ? " (unknown header)" : " - " + x.Name)}");
        }

        if (x.EndCode is not null || x.EndCodeMeaning is not null)
        {
            w.WriteLine($"End code:   {x.EndCode ?? "(none)"} - {x.EndCodeMeaning}");
        }

        if (x.Text is not null)
        {
            w.WriteLine($"Text:       {(x.Text.Length == 0 ? "(none)" : x.Text)}");
        }

        if (x.FcsFound is not null)
        {
            bool ok = string.Equals(x.FcsFound, x.FcsExpected, StringComparison.Ordinal);
            w.WriteLine($"FCS:        found {x.FcsFound}, expected {x.FcsExpected}: {(ok ? "OK" : "MISMATCH")}");
        }

        w.WriteLine($"Ending:     {(x.Final == false ? "CR (more frames follow)" : "*CR (final frame)")}");
        foreach (KeyValuePair<string, object?> field in x.Fields)
        {
            w.WriteLine($"  {field.Key}: {Human(field.Value)}");
        }

        foreach (string note in x.Notes)
        {
            w.WriteLine($"Note:       {note}");
        }

        foreach (string problem in x.Problems)
        {
            w.WriteLine($"Problem:    {problem}");
        }

        w.WriteLine($"Valid:      {(x.Valid ? "yes" : "no")}");
    }

    /// <summary>Writes the explanation as one JSON document.</summary>
    public static void WriteJson(Utf8JsonWriter j, FrameExplanation x)
    {
        j.WriteStartObject();
        j.WriteBoolean("valid", x.Valid);
        j.WriteString("frame", x.Frame);
        j.WriteString("direction", x.IsResponse ? "response" : "command");
        WriteNullable(j, "unit", x.Unit);
        WriteNullable(j, "header", x.Header);
        WriteNullable(j, "name", x.Name);
        WriteNullable(j, "endCode", x.EndCode);
        WriteNullable(j, "endCodeMeaning", x.EndCodeMeaning);
        if (x.FcsFound is null)
        {
            j.WriteNull("fcs");
        }
        else
        {
            j.WriteStartObject("fcs");
            j.WriteString("expected", x.FcsExpected);
            j.WriteString("found", x.FcsFound);
            j.WriteBoolean("ok", string.Equals(x.FcsFound, x.FcsExpected, StringComparison.Ordinal));
            j.WriteEndObject();
        }

        j.WriteBoolean("final", x.Final != false);
        WriteNullable(j, "text", x.Text);
        if (x.IsResponse)
        {
            WriteNullable(j, "data", x.Data);
        }

        j.WriteStartObject("fields");
        foreach (KeyValuePair<string, object?> field in x.Fields)
        {
            j.WritePropertyName(field.Key);
            WriteValue(j, field.Value);
        }

        j.WriteEndObject();
        j.WriteStartArray("notes");
        foreach (string note in x.Notes)
        {
            j.WriteStringValue(note);
        }

        j.WriteEndArray();
        j.WriteStartArray("problems");
        foreach (string problem in x.Problems)
        {
            j.WriteStringValue(problem);
        }

        j.WriteEndArray();
        j.WriteEndObject();
    }

    private static void WriteNullable(Utf8JsonWriter j, string name, string? value)
    {
        if (value is null)
        {
            j.WriteNull(name);
        }
        else
        {
            j.WriteString(name, value);
        }
    }

    private static void WriteNullable(Utf8JsonWriter j, string name, int? value)
    {
        if (value is null)
        {
            j.WriteNull(name);
        }
        else
        {
            j.WriteNumber(name, value.Value);
        }
    }

    private static void WriteValue(Utf8JsonWriter j, object? value)
    {
        switch (value)
        {
            case null:
                j.WriteNullValue();
                break;
            case string s:
                j.WriteStringValue(s);
                break;
            case long l:
                j.WriteNumberValue(l);
                break;
            case bool b:
                j.WriteBooleanValue(b);
                break;
            case long[] ls:
                j.WriteStartArray();
                foreach (long l in ls)
                {
                    j.WriteNumberValue(l);
                }

                j.WriteEndArray();
                break;
            case bool[] bs:
                j.WriteStartArray();
                foreach (bool b in bs)
                {
                    j.WriteBooleanValue(b);
                }

                j.WriteEndArray();
                break;
            case string[] ss:
                j.WriteStartArray();
                foreach (string s in ss)
                {
                    j.WriteStringValue(s);
                }

                j.WriteEndArray();
                break;
            default:
                j.WriteStringValue(Convert.ToString(value, CultureInfo.InvariantCulture));
                break;
        }
    }

    private static string Human(object? value) => value switch
    {
        null => "(none)",
        bool b => b ? "yes" : "no",
        long[] ls => string.Join(" ", ls.Select(l => $"0x{l:X4}({l})")),
        bool[] bs => string.Join(" ", bs.Select(b => b ? "1" : "0")),
        string[] ss => string.Join(" ", ss),
        string s when s.Length == 0 => "(empty)",
        _ => Convert.ToString(value, CultureInfo.InvariantCulture) ?? string.Empty,
    };

    /// <summary>Reads FINS fields (two hex characters a byte) in order, recording each as a field.</summary>
    private ref struct HexFields
    {
        private readonly FrameExplanation _x;
        private readonly ReadOnlySpan<byte> _text;
        private int _at;

        public HexFields(FrameExplanation x, ReadOnlySpan<byte> text)
        {
            _x = x;
            _text = text;
            _at = 0;
        }

        public bool Chars(string name, int count, out string value)
        {
            if (_at + count > _text.Length)
            {
                value = string.Empty;
                Fail($"The frame ends before the FINS field {name}.");
                return false;
            }

            value = Encoding.ASCII.GetString(_text.Slice(_at, count));
            _at += count;
            return true;
        }

        public bool Byte(string name, out byte value)
        {
            value = 0;
            if (!Chars(name, 2, out string s))
            {
                return false;
            }

            if (!HexAscii.TryParseByte(Encoding.ASCII.GetBytes(s), out value))
            {
                Fail($"The FINS field {name} '{s}' is not two hex digits.");
                return false;
            }

            _x.Field(name, s);
            return true;
        }

        public bool Word(string name, out ushort value)
        {
            value = 0;
            if (!Chars(name, 4, out string s))
            {
                return false;
            }

            if (!HexAscii.TryParseWord(Encoding.ASCII.GetBytes(s), out value))
            {
                Fail($"The FINS field {name} '{s}' is not four hex digits.");
                return false;
            }

            _x.Field(name, s);
            return true;
        }

        public string Rest()
        {
            string rest = Encoding.ASCII.GetString(_text[_at..]);
            _at = _text.Length;
            return rest;
        }

        public readonly void Fail(string problem) => _x.Problems.Add(problem);
    }
}
