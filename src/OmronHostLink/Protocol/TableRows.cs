namespace OmronHostLink.Protocol;

/// <summary>Extends a command table (C-mode or FINS): rows added in order, a row whose key is present replacing it.</summary>
internal static class TableRows
{
    /// <summary><paramref name="rows"/> with <paramref name="added"/>: each added row replaces the row with its key, or goes last.</summary>
    public static TRow[] With<TRow, TKey>(IReadOnlyList<TRow> rows, IEnumerable<TRow> added, Func<TRow, TKey> key)
        where TKey : IEquatable<TKey>
    {
        var list = new List<TRow>(rows);
        foreach (TRow row in added)
        {
            int at = list.FindIndex(r => key(r).Equals(key(row)));
            if (at >= 0)
            {
                list[at] = row;
            }
            else
            {
                list.Add(row);
            }
        }

        return list.ToArray();
    }
}
