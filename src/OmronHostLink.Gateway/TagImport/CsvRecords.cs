using System.Text;

namespace OmronHostLink.Gateway.TagImport;

/// <summary>
/// Reads CSV as spreadsheets and Kepware write it (RFC 4180): fields separated by commas, optionally in double quotes,
/// a quote inside quotes doubled, line breaks inside quotes kept. Blank lines are skipped; each record knows its line.
/// </summary>
internal static class CsvRecords
{
    /// <summary>Reads every record of a tag file; a file that is not CSV becomes a problem on line 1 and null.</summary>
    internal static List<CsvRecord>? ReadTagFile(TextReader reader, List<TagImportProblem> problems)
    {
        try
        {
            return Read(reader);
        }
        catch (FormatException e)
        {
            problems.Add(new TagImportProblem(1, "the file is not CSV: " + e.Message));
            return null;
        }
    }

    /// <summary>Reads every record.</summary>
    /// <exception cref="FormatException">A quoted field is not closed, or text follows a closing quote; the message names the line.</exception>
    public static List<CsvRecord> Read(TextReader reader)
    {
        ArgumentNullException.ThrowIfNull(reader);
        var records = new List<CsvRecord>();
        var fields = new List<string>();
        var field = new StringBuilder();
        int line = 1;
        int recordLine = 1;
        bool quoted = false;
        bool afterQuote = false;
        bool any = false;
        int c;
        while ((c = reader.Read()) >= 0)
        {
            char ch = (char)c;
            if (quoted)
            {
                if (ch == '"')
                {
                    if (reader.Peek() == '"')
                    {
                        reader.Read();
                        field.Append('"');
                    }
                    else
                    {
                        quoted = false;
                        afterQuote = true;
                    }
                }
                else
                {
                    if (ch == '\n')
                    {
                        line++;
                    }

                    field.Append(ch);
                }

                continue;
            }

            switch (ch)
            {
                case '"' when field.Length == 0 && !afterQuote:
                    quoted = true;
                    any = true;
                    break;
                case ',':
                    fields.Add(field.ToString());
                    field.Clear();
                    afterQuote = false;
                    any = true;
                    break;
                case '\r':
                    break;
                case '\n':
                    End();
                    line++;
                    recordLine = line;
                    break;
                default:
                    if (afterQuote)
                    {
                        if (ch is ' ' or '\t')
                        {
                            break;
                        }

                        throw new FormatException($"line {line}: '{ch}' after the closing quote of a field; a quote inside a quoted field is written twice (\"\").");
                    }

                    field.Append(ch);
                    any = true;
                    break;
            }
        }

        if (quoted)
        {
            throw new FormatException($"line {recordLine}: a quoted field is not closed before the end of the file.");
        }

        End();
        return records;

        void End()
        {
            if (any)
            {
                fields.Add(field.ToString());
                records.Add(new CsvRecord(recordLine, fields.ToArray()));
            }

            fields.Clear();
            field.Clear();
            afterQuote = false;
            any = false;
        }
    }
}
