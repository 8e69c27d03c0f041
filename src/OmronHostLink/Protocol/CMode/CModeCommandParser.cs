using System.Text;

namespace OmronHostLink.Protocol.CMode;

/// <summary>Rebuilds typed C-mode commands from received text, refusing what a CS/CJ PLC refuses with the end code it answers.</summary>
internal static class CModeCommandParser
{
    public static CModeCommand Parse(ReadOnlySpan<byte> header, ReadOnlySpan<byte> text)
    {
        try
        {
            return ParseChecked(header, text);
        }
        catch (ArgumentException e)
        {
            // The typed commands' constructors refuse what they cannot encode (TS text holding '@', '*' or CR, for one)
            // with ArgumentException, right for host-side callers; received text is the PLC's to refuse, with the
            // documented CModeCommandRejectedException (fuzzing found ArgumentException escaping Parse).
            throw Reject(EndCode.FormatError, e.Message);
        }
    }

    private static CModeCommand ParseChecked(ReadOnlySpan<byte> header, ReadOnlySpan<byte> text)
    {
        if (header.Length != 2)
        {
            throw Reject(EndCode.UndefinedHeader, "A header has two characters.");
        }

        if (CModeAreaInfo.TryFromHeader(header, out CModeArea area, out bool write))
        {
            return write ? ParseWrite(area, text) : ParseRead(area, text);
        }

        string h = Encoding.ASCII.GetString(header.ToArray());
        switch (h)
        {
            case CModeHeaders.StatusRead:
                return WithoutText(text, StatusReadCommand.Instance);
            case CModeHeaders.ModelRead:
                return WithoutText(text, ModelReadCommand.Instance);
            case CModeHeaders.ForcedSetResetCancel:
                return WithoutText(text, ForcedCancelCommand.Instance);
            case CModeHeaders.Abort:
                return WithoutText(text, AbortCommand.Instance);
            case CModeHeaders.StatusChange:
                ExpectLength(text, 2, h);
                if (!HexAscii.TryParseByte(text, out byte code) || !StatusChangeCommand.TryGetMode(code, out PlcMode mode))
                {
                    throw Reject(EndCode.EntryNumberDataError, "SC mode must be 00, 02 or 03.");
                }

                return new StatusChangeCommand(mode);
            case CModeHeaders.ErrorRead:
                ExpectLength(text, 2, h);
                if (!HexAscii.TryParseDecimal(text, out int clear) || clear > 1)
                {
                    throw Reject(EndCode.EntryNumberDataError, "MF error clear must be 00 or 01.");
                }

                return new ErrorReadCommand(clear == 1);
            case CModeHeaders.Test:
                if (text.Length > TestCommand.MaxTextLength)
                {
                    throw Reject(EndCode.FrameLengthError, "TS text is too long.");
                }

                return new TestCommand(Encoding.ASCII.GetString(text.ToArray()));
            case CModeHeaders.ForcedSet:
            case CModeHeaders.ForcedReset:
                return ParseForce(h == CModeHeaders.ForcedSet, text);
            case CModeHeaders.MultipleForcedSetReset:
                return ParseMultipleForce(text);
            default:
                throw Reject(EndCode.UndefinedHeader, $"Unknown header {FrameText.Printable(header)}.");
        }
    }

    private static AreaReadCommand ParseRead(CModeArea area, ReadOnlySpan<byte> text)
    {
        int bankLength = CModeAreaInfo.BankLength(area);
        ExpectLength(text, AreaReadCommand.GetTextLength(area), CModeAreaInfo.ReadHeader(area));
        int bank = ParseBank(area, text);
        if (!HexAscii.TryParseDecimal(text.Slice(bankLength, 4), out int begin) || !HexAscii.TryParseDecimal(text.Slice(bankLength + 4, 4), out int count))
        {
            throw Reject(EndCode.EntryNumberDataError, "Begin word and count must be decimal digits.");
        }

        return Checked(() => new AreaReadCommand(area, begin, count, bank));
    }

    private static AreaWriteCommand ParseWrite(CModeArea area, ReadOnlySpan<byte> text)
    {
        int fixedLength = AreaWriteCommand.GetFixedTextLength(area);
        if (text.Length < fixedLength + 4 || (text.Length - fixedLength) % 4 != 0)
        {
            throw Reject(EndCode.FormatError, "Write data must be whole 4-digit words after the begin word.");
        }

        int bank = ParseBank(area, text);
        if (!HexAscii.TryParseDecimal(text.Slice(fixedLength - 4, 4), out int begin))
        {
            throw Reject(EndCode.EntryNumberDataError, "Begin word must be decimal digits.");
        }

        var words = new ushort[(text.Length - fixedLength) / 4];
        if (!HexAscii.TryParseWords(text.Slice(fixedLength), words))
        {
            throw Reject(EndCode.EntryNumberDataError, "Write data must be hexadecimal.");
        }

        return Checked(() => new AreaWriteCommand(area, begin, words, bank));
    }

    private static int ParseBank(CModeArea area, ReadOnlySpan<byte> text)
    {
        if (area != CModeArea.Em)
        {
            return 0;
        }

        if (!HexAscii.TryParseByte(text.Slice(0, 2), out byte bank))
        {
            throw Reject(EndCode.EntryNumberDataError, "EM bank must be two hex digits.");
        }

        return bank;
    }

    private static ForceBitCommand ParseForce(bool set, ReadOnlySpan<byte> text)
    {
        ExpectLength(text, 10, set ? CModeHeaders.ForcedSet : CModeHeaders.ForcedReset);
        if (!ForceAreaInfo.TryParse(text.Slice(0, 4), out ForceArea area)
            || !HexAscii.TryParseDecimal(text.Slice(4, 4), out int word)
            || !HexAscii.TryParseDecimal(text.Slice(8, 2), out int bit))
        {
            throw Reject(EndCode.EntryNumberDataError, "Area name, word or bit is not valid.");
        }

        return Checked(() => new ForceBitCommand(set, area, word, bit));
    }

    private static MultipleForceCommand ParseMultipleForce(ReadOnlySpan<byte> text)
    {
        ExpectLength(text, 24, CModeHeaders.MultipleForcedSetReset);
        if (!ForceAreaInfo.TryParse(text.Slice(0, 4), out ForceArea area) || !HexAscii.TryParseDecimal(text.Slice(4, 4), out int word))
        {
            throw Reject(EndCode.EntryNumberDataError, "Area name or word is not valid.");
        }

        var actions = new ForceAction[16];
        for (int i = 0; i < 16; i++)
        {
            int digit = text[8 + i] - '0';
            if (digit is not (0 or 2 or 3 or 4 or 5 or 8))
            {
                throw Reject(EndCode.EntryNumberDataError, $"FK action for bit {15 - i} is not valid.");
            }

            actions[i] = (ForceAction)digit;
        }

        return Checked(() => new MultipleForceCommand(area, word, actions));
    }

    private static CModeCommand WithoutText(ReadOnlySpan<byte> text, CModeCommand command)
    {
        ExpectLength(text, 0, command.Header);
        return command;
    }

    private static void ExpectLength(ReadOnlySpan<byte> text, int length, string header)
    {
        if (text.Length != length)
        {
            throw Reject(EndCode.FormatError, $"{header} takes {length} characters of text; {text.Length} were sent.");
        }
    }

    private static T Checked<T>(Func<T> create)
    {
        try
        {
            return create();
        }
        catch (ArgumentException e)
        {
            throw Reject(EndCode.EntryNumberDataError, e.Message);
        }
    }

    private static CModeCommandRejectedException Reject(EndCode code, string message) => new(code, message);
}
