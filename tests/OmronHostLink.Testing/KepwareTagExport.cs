using System.Globalization;
using System.Text;

namespace OmronHostLink.Testing;

/// <summary>A Kepware (KEPServerEX) tag export as a plant's server writes one: its header, then one row a tag.</summary>
public static class KepwareTagExport
{
    /// <summary>The export of <paramref name="rows"/> (tag name, Kepware address, data type), read only, at <paramref name="scanRateMs"/>.</summary>
    public static string Csv(IEnumerable<(string Name, string Address, string DataType)> rows, int scanRateMs)
    {
        var csv = new StringBuilder();
        csv.AppendLine("\"Tag Name\",\"Address\",\"Data Type\",\"Respect Data Type\",\"Client Access\",\"Scan Rate\",\"Scaling\",\"Raw Low\",\"Raw High\",\"Scaled Low\",\"Scaled High\",\"Scaled Data Type\",\"Clamp Low\",\"Clamp High\",\"Eng Units\",\"Description\",\"Negate Value\"");
        foreach ((string name, string address, string dataType) in rows)
        {
            csv.AppendLine(CultureInfo.InvariantCulture, $"\"{name}\",\"{address}\",\"{dataType}\",\"1\",\"RO\",\"{scanRateMs}\",\"\",\"\",\"\",\"\",\"\",\"\",\"\",\"\",\"\",\"\",\"0\"");
        }

        return csv.ToString();
    }
}
