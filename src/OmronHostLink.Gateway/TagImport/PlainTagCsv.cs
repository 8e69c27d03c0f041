using System.Globalization;

namespace OmronHostLink.Gateway.TagImport;

/// <summary>
/// Gateway tags from a plain CSV: a header naming <c>name</c>, <c>address</c>, <c>type</c> and <c>writable</c> (and,
/// optionally, <c>count</c> and <c>interval</c> in milliseconds), in any order; addresses and types as the gateway's
/// configuration spells them. Every bad row is reported with its line and then nothing is imported.
/// </summary>
internal static class PlainTagCsv
{
    /// <summary>Reads a file.</summary>
    public static TagImportResult Import(TextReader reader)
    {
        var tags = new List<ImportedTag>();
        var problems = new List<TagImportProblem>();
        List<CsvRecord>? records = CsvRecords.ReadTagFile(reader, problems);
        if (records is null || records.Count == 0)
        {
            return TagImportResult.From(tags, problems);
        }

        Dictionary<string, int> columns = KepwareTagCsv.Columns(records[0]);
        foreach (string required in new[] { "name", "address", "type", "writable" })
        {
            if (!columns.ContainsKey(required))
            {
                problems.Add(new TagImportProblem(records[0].Line, $"the header has no '{required}' column; it names name,address,type,writable (and optionally count, interval)."));
            }
        }

        if (problems.Count > 0)
        {
            return TagImportResult.From(tags, problems);
        }

        foreach (CsvRecord record in records.Skip(1))
        {
            string Field(string column) => columns.TryGetValue(column, out int i) && i < record.Fields.Count ? record.Fields[i].Trim() : "";
            string name = Field("name");
            PlcValueType type = default;
            PlcAddress address = default;
            bool writable = false;
            int count = 1;
            TimeSpan? interval = null;
            string addressError = "";
            string? why = TagNames.Check(name) is { } badName ? "name " + badName
                : !PlcValueTypes.TryParse(Field("type"), out type) ? $"type '{Field("type")}' is not one of {string.Join(", ", PlcValueTypes.Names)}"
                : !TryAddress(Field("address"), out address, out addressError) ? addressError
                : !TryWritable(Field("writable"), out writable) ? $"writable '{Field("writable")}' is not true or false"
                : !TryCount(Field("count"), out count) ? $"count '{Field("count")}' is not a whole number from 1 to 10000"
                : !TryInterval(Field("interval"), out interval) ? $"interval '{Field("interval")}' is not a whole number of milliseconds of 10 or more"
                : type == PlcValueType.Bit && !address.IsBit && address.Area is not (PlcArea.Timer or PlcArea.Counter) ? $"a bit tag names a bit ({Field("address")}.00 to .15) or a timer/counter completion flag"
                : type != PlcValueType.Bit && address.IsBit ? $"address {Field("address")} names a bit; its type is bit, not {Field("type")}"
                : null;
            if (why is not null)
            {
                problems.Add(new TagImportProblem(record.Line, name.Length == 0 ? why : $"tag '{name}': {why}."));
                continue;
            }

            tags.Add(new ImportedTag(record.Line, name, address.ToString(), type, count, writable, interval));
        }

        return TagImportResult.From(tags, problems);
    }

    private static bool TryAddress(string text, out PlcAddress address, out string error)
    {
        error = "";
        try
        {
            address = PlcAddress.Parse(text);
            return true;
        }
        catch (FormatException e)
        {
            address = default;
            error = e.Message.TrimEnd('.');
            return false;
        }
    }

    private static bool TryWritable(string text, out bool writable)
    {
        switch (text.ToUpperInvariant())
        {
            case "" or "FALSE" or "NO" or "0":
                writable = false;
                return true;
            case "TRUE" or "YES" or "1":
                writable = true;
                return true;
            default:
                writable = false;
                return false;
        }
    }

    private static bool TryCount(string text, out int count)
    {
        count = 1;
        return text.Length == 0 || (int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out count) && count is >= 1 and <= 10000);
    }

    private static bool TryInterval(string text, out TimeSpan? interval)
    {
        interval = null;
        if (text.Length == 0)
        {
            return true;
        }

        if (!int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out int ms) || ms < 10)
        {
            return false;
        }

        interval = TimeSpan.FromMilliseconds(ms);
        return true;
    }
}
