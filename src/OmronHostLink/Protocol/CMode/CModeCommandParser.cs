namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// Rebuilds typed C-mode commands from received text by looking the header up in a <see cref="CModeCommandTable"/>,
/// refusing what a CS/CJ PLC refuses with the end code it answers. The parsing of each command's text is its row's.
/// </summary>
internal static class CModeCommandParser
{
    public static CModeCommand Parse(CModeCommandTable table, ReadOnlySpan<byte> header, ReadOnlySpan<byte> text)
    {
        if (header.Length != 2)
        {
            throw Reject(EndCode.UndefinedHeader, "A header has two characters.");
        }

        CModeCommandRow? row = table.Find(header, text);
        if (row?.Parse is null || !row.IsCommand)
        {
            throw Reject(EndCode.UndefinedHeader, $"Unknown header {FrameText.Printable(header)}.");
        }

        try
        {
            return row.Parse(text.Slice(row.SubHeaderLength));
        }
        catch (ArgumentException e)
        {
            // The typed commands' constructors refuse what they cannot encode (TS text holding '@', '*' or CR, for one)
            // with ArgumentException, right for host-side callers; received text is the PLC's to refuse, with the
            // documented CModeCommandRejectedException (fuzzing found ArgumentException escaping Parse).
            throw Reject(EndCode.FormatError, e.Message);
        }
    }

    /// <summary>Refuses text whose length is not <paramref name="length"/> (end code 14).</summary>
    public static void ExpectLength(ReadOnlySpan<byte> text, int length, string header)
    {
        if (text.Length != length)
        {
            throw Reject(EndCode.FormatError, $"{header} takes {length} characters of text; {text.Length} were sent.");
        }
    }

    /// <summary>Creates a command, turning a range the constructor refuses into end code 15.</summary>
    public static T Checked<T>(Func<T> create)
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

    /// <summary>The refusal a PLC answers with <paramref name="code"/>.</summary>
    public static CModeCommandRejectedException Reject(EndCode code, string message) => new(code, message);
}
