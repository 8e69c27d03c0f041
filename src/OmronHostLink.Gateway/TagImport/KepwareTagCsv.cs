using System.Globalization;
using System.Text.RegularExpressions;

namespace OmronHostLink.Gateway.TagImport;

/// <summary>
/// Gateway tags from a Kepware (KEPServerEX) CSV tag export of an Omron Host Link device. The columns, the address
/// syntax and the data types are translated as docs/tag-import.md tables them; every row that cannot be translated is
/// reported with its line and then nothing is imported.
/// </summary>
internal static partial class KepwareTagCsv
{
    /// <summary>The columns read; the others of an export (Respect Data Type, Raw/Scaled Low/High, Clamp, Eng Units…) are ignored unless they ask for something the gateway does not do.</summary>
    private const string TagName = "Tag Name";
    private const string Address = "Address";
    private const string DataType = "Data Type";
    private const string ClientAccess = "Client Access";
    private const string ScanRate = "Scan Rate";
    private const string Scaling = "Scaling";
    private const string NegateValue = "Negate Value";
    private const string Description = "Description";

    /// <summary>Reads an export.</summary>
    public static TagImportResult Import(TextReader reader)
    {
        var tags = new List<ImportedTag>();
        var problems = new List<TagImportProblem>();
        List<CsvRecord>? records = CsvRecords.ReadTagFile(reader, problems);
        if (records is null || records.Count == 0)
        {
            return TagImportResult.From(tags, problems);
        }

        var columns = Columns(records[0]);
        foreach (string required in new[] { TagName, Address })
        {
            if (!columns.ContainsKey(required))
            {
                problems.Add(new TagImportProblem(records[0].Line, $"the header has no '{required}' column; a Kepware tag export starts with \"Tag Name\",\"Address\",\"Data Type\",…"));
            }
        }

        if (problems.Count > 0)
        {
            return TagImportResult.From(tags, problems);
        }

        foreach (CsvRecord record in records.Skip(1))
        {
            if (TryTranslate(record, columns, out ImportedTag? tag, out string error))
            {
                tags.Add(tag!);
            }
            else
            {
                problems.Add(new TagImportProblem(record.Line, error));
            }
        }

        return TagImportResult.From(tags, problems);
    }

    internal static Dictionary<string, int> Columns(CsvRecord header)
    {
        var columns = new Dictionary<string, int>(StringComparer.OrdinalIgnoreCase);
        for (int i = 0; i < header.Fields.Count; i++)
        {
            columns.TryAdd(header.Fields[i].Trim(), i);
        }

        return columns;
    }

    private static string Field(CsvRecord record, Dictionary<string, int> columns, string name)
        => columns.TryGetValue(name, out int i) && i < record.Fields.Count ? record.Fields[i].Trim() : "";

    private static bool TryTranslate(CsvRecord record, Dictionary<string, int> columns, out ImportedTag? tag, out string error)
    {
        tag = null;
        string name = Field(record, columns, TagName);
        string address = Field(record, columns, Address);
        string dataType = Field(record, columns, DataType);
        if (TagNames.Check(name) is { } badName)
        {
            error = $"Tag Name {badName}.";
            return false;
        }

        if (address.Length == 0)
        {
            error = $"tag '{name}' has no Address.";
            return false;
        }

        if (!TryAccess(Field(record, columns, ClientAccess), out bool writable, out error)
            || !TryScanRate(Field(record, columns, ScanRate), out TimeSpan? interval, out error)
            || !TryUnscaled(Field(record, columns, Scaling), Field(record, columns, NegateValue), out error))
        {
            error = $"tag '{name}': {error}";
            return false;
        }

        if (!TryAddress(address, dataType, out string core, out PlcValueType type, out int count, out error))
        {
            error = $"tag '{name}', Address '{address}' ({(dataType.Length == 0 ? "Default" : dataType)}): {error}";
            return false;
        }

        string description = Field(record, columns, Description);
        tag = new ImportedTag(record.Line, name, core, type, count, writable, interval, description.Length == 0 ? null : description);
        return true;
    }

    /// <summary>
    /// Translates a Kepware address and data type: the area names (DM, HR, AR, LR, IR, TC…) are the core's own; the
    /// array suffix (<c>[n]</c> or <c>[rows][cols]</c>) becomes the count, the string suffix (<c>.lenH</c>) the length.
    /// </summary>
    internal static bool TryAddress(string text, string dataType, out string address, out PlcValueType type, out int count, out string error)
    {
        address = "";
        type = PlcValueType.Word;
        count = 1;
        error = "";

        Match array = ArraySuffix().Match(text);
        string body = array.Groups["body"].Value;
        int elements = 1;
        bool isArray = array.Groups["a"].Success;
        if (isArray)
        {
            if (!int.TryParse(array.Groups["a"].Value, NumberStyles.None, CultureInfo.InvariantCulture, out int a)
                || !int.TryParse(array.Groups["b"].Success ? array.Groups["b"].Value : "1", NumberStyles.None, CultureInfo.InvariantCulture, out int b)
                || a < 1 || b < 1 || (long)a * b > 10000)
            {
                error = "the array dimensions must be 1 or more, at most 10000 elements in all";
                return false;
            }

            elements = a * b;
        }

        Match text2 = StringSuffix().Match(body);
        bool isString = text2.Success;
        if (isString)
        {
            body = text2.Groups["body"].Value;
        }

        if (!TryDataType(dataType, out KepwareType kind, out bool typeIsArray, out error))
        {
            return false;
        }

        if (typeIsArray && !isArray)
        {
            error = $"an array data type needs the dimensions after the address, e.g. {body} [4]";
            return false;
        }

        if (kind == KepwareType.Default)
        {
            kind = isString ? KepwareType.String : body.Contains('.') ? KepwareType.Boolean : KepwareType.Word;
        }

        if (!PlcAddress.TryParse(body, out PlcAddress parsed))
        {
            try
            {
                PlcAddress.Parse(body);
            }
            catch (FormatException e)
            {
                error = e.Message;
            }

            return false;
        }

        if (kind == KepwareType.String)
        {
            if (!isString)
            {
                error = $"a String tag names its length and byte order after the word, e.g. {body}.20H";
                return false;
            }

            char order = char.ToUpperInvariant(text2.Groups["order"].Value[0]);
            if (order != 'H')
            {
                error = order == 'L'
                    ? "LoHi strings (.lenL: the first character in the low byte) are not read by the gateway; it reads text high byte first (.lenH)"
                    : "strings of one character a word (.lenD, .lenE) are not read by the gateway; it reads two characters a word, high byte first (.lenH)";
                return false;
            }

            count = int.Parse(text2.Groups["len"].Value, CultureInfo.InvariantCulture);
            if (count < 1 || isArray)
            {
                error = isArray ? "a String tag cannot be an array" : "a string's length must be 1 or more";
                return false;
            }

            type = PlcValueType.String;
            address = parsed.ToString();
            return true;
        }

        if (isString)
        {
            error = $"the .lenH/.lenL/.lenD/.lenE suffix is for String tags, not {kind}";
            return false;
        }

        if (kind == KepwareType.Boolean)
        {
            bool completionFlag = parsed.Area is PlcArea.Timer or PlcArea.Counter && !parsed.IsBit;
            if (!parsed.IsBit && !completionFlag)
            {
                error = $"a Boolean tag names a bit: {body}.00 to {body}.15";
                return false;
            }

            if (isArray)
            {
                error = "Boolean tags cannot be arrays (Kepware's own rule for this driver); import each bit as its own tag";
                return false;
            }

            type = PlcValueType.Bit;
            address = parsed.ToString();
            return true;
        }

        if (parsed.IsBit)
        {
            error = $"a bit address holds a Boolean, not {kind}";
            return false;
        }

        type = kind switch
        {
            KepwareType.Word => PlcValueType.Word,
            KepwareType.Short => PlcValueType.Int16,
            KepwareType.Bcd => PlcValueType.Bcd,
            KepwareType.Long => PlcValueType.Int32,
            KepwareType.DWord => PlcValueType.UInt32,
            KepwareType.Float => PlcValueType.Float,
            KepwareType.Double => PlcValueType.Double,
            _ => PlcValueType.Bcd32,
        };
        count = elements;
        address = parsed.ToString();
        return true;
    }

    private enum KepwareType
    {
        Default,
        Boolean,
        Word,
        Short,
        Bcd,
        Long,
        DWord,
        Float,
        Double,
        Lbcd,
        String,
    }

    private static bool TryDataType(string text, out KepwareType type, out bool isArray, out string error)
    {
        error = "";
        string t = text.Trim();
        isArray = t.EndsWith(" Array", StringComparison.OrdinalIgnoreCase);
        if (isArray)
        {
            t = t.Substring(0, t.Length - " Array".Length).TrimEnd();
        }

        switch (t.ToUpperInvariant())
        {
            case "" or "DEFAULT": type = KepwareType.Default; break;
            case "BOOLEAN": type = KepwareType.Boolean; break;
            case "WORD": type = KepwareType.Word; break;
            case "SHORT": type = KepwareType.Short; break;
            case "BCD": type = KepwareType.Bcd; break;
            case "LONG": type = KepwareType.Long; break;
            case "DWORD": type = KepwareType.DWord; break;
            case "FLOAT": type = KepwareType.Float; break;
            case "DOUBLE": type = KepwareType.Double; break;
            case "LBCD": type = KepwareType.Lbcd; break;
            case "STRING": type = KepwareType.String; break;
            default:
                type = default;
                error = $"Data Type '{text}' has no counterpart in the gateway; use Boolean, Word, Short, BCD, Long, DWord, Float, Double, LBCD or String (or their arrays)";
                return false;
        }

        if (isArray && type is KepwareType.Boolean or KepwareType.String or KepwareType.Default)
        {
            error = $"Data Type '{text}' cannot be an array";
            return false;
        }

        return true;
    }

    private static bool TryAccess(string text, out bool writable, out string error)
    {
        error = "";
        switch (text.Replace(" ", "", StringComparison.Ordinal).ToUpperInvariant())
        {
            case "R/W" or "RW" or "READ/WRITE":
                writable = true;
                return true;
            case "" or "RO" or "READONLY":
                writable = false;
                return true;
            default:
                writable = false;
                error = text.Equals("WO", StringComparison.OrdinalIgnoreCase) || text.Replace(" ", "", StringComparison.Ordinal).Equals("WriteOnly", StringComparison.OrdinalIgnoreCase)
                    ? "Client Access 'Write Only' is not supported: every gateway tag is polled"
                    : $"Client Access '{text}' is not RO or R/W";
                return false;
        }
    }

    private static bool TryScanRate(string text, out TimeSpan? interval, out string error)
    {
        error = "";
        interval = null;
        if (text.Length == 0)
        {
            return true;
        }

        if (!int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out int ms) || ms < 10)
        {
            error = $"Scan Rate '{text}' is not a whole number of milliseconds of 10 or more";
            return false;
        }

        interval = TimeSpan.FromMilliseconds(ms);
        return true;
    }

    private static bool TryUnscaled(string scaling, string negate, out string error)
    {
        error = "";
        if (scaling.Length > 0 && !scaling.Equals("None", StringComparison.OrdinalIgnoreCase))
        {
            error = $"Scaling '{scaling}' is not done by the gateway, which publishes the PLC's values as read; remove it or scale in the consumer";
            return false;
        }

        if (negate is "1" || negate.Equals("true", StringComparison.OrdinalIgnoreCase))
        {
            error = "Negate Value is not done by the gateway, which publishes the PLC's values as read";
            return false;
        }

        return true;
    }

    // "DM0100 [4]", "DM0100[2][5]": the address, then one or two dimensions.
    [GeneratedRegex(@"^(?<body>.*?)\s*(?:\[(?<a>[^\]]*)\](?:\[(?<b>[^\]]*)\])?)?$", RegexOptions.CultureInvariant)]
    private static partial Regex ArraySuffix();

    // "DM0100.20H": 20 characters, HiLo.
    [GeneratedRegex(@"^(?<body>[A-Za-z]*\s*\d+)\.(?<len>\d{1,3})(?<order>[HhLlDdEe])$", RegexOptions.CultureInvariant)]
    private static partial Regex StringSuffix();
}
