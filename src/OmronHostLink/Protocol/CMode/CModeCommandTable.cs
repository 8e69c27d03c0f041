namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// The C-mode command set as rows (<see cref="CModeCommandRow"/>): what the parser, the simulator, <c>explain</c> and
/// the planner look commands up in. <see cref="Standard"/> is the set this library knows; <see cref="With"/> extends a
/// table (a test's fake command, a model profile's extra command).
/// </summary>
internal sealed class CModeCommandTable
{
    private readonly CModeCommandRow[] _rows;

    private CModeCommandTable(CModeCommandRow[] rows) => _rows = rows;

    /// <summary>The commands and answers of the manuals, those this library executes and those it only names.</summary>
    public static CModeCommandTable Standard { get; } = new(CModeCommands.All());

    /// <summary>The rows, in the manuals' order.</summary>
    public IReadOnlyList<CModeCommandRow> Rows => _rows;

    /// <summary>This table with <paramref name="rows"/> added; a row whose key is already present replaces it.</summary>
    public CModeCommandTable With(params CModeCommandRow[] rows)
        => new CModeCommandTable(TableRows.With(_rows, rows, r => r.Key));

    /// <summary>
    /// The row of a header and the text after it: a row with a sub-header matches when the text starts with it; a
    /// header whose rows all have sub-headers matches none of them without one.
    /// </summary>
    public CModeCommandRow? Find(ReadOnlySpan<byte> header, ReadOnlySpan<byte> text)
    {
        CModeCommandRow? plain = null;
        foreach (CModeCommandRow row in _rows)
        {
            if (!CModeHeaders.Is(header, row.Header))
            {
                continue;
            }

            if (row.SubHeader is null)
            {
                plain ??= row;
            }
            else if (text.Length >= row.SubHeaderLength && CModeHeaders.Is(text.Slice(0, 2), row.SubHeader))
            {
                return row;
            }
        }

        return plain;
    }

    /// <summary>Whether any row has this header (with or without a sub-header).</summary>
    public bool Knows(ReadOnlySpan<byte> header)
    {
        foreach (CModeCommandRow row in _rows)
        {
            if (CModeHeaders.Is(header, row.Header))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>The manuals' name of a header (of its sub-header's row when the text names one), or null.</summary>
    public string? Name(string header, ReadOnlySpan<byte> text = default)
    {
        byte[] h = [(byte)header[0], (byte)(header.Length > 1 ? header[1] : 0)];
        if (header.Length != 2)
        {
            return null;
        }

        if (Find(h, text) is { } row)
        {
            return row.Name;
        }

        // A header known only with a sub-header (QQ without MR or IR): the names of its rows.
        string[] names = _rows.Where(r => r.Header == header).Select(r => r.Name).ToArray();
        return names.Length == 0 ? null : string.Join(" / ", names);
    }
}
