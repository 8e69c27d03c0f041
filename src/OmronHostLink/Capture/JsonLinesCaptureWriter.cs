using System.Globalization;
using System.Text;

namespace OmronHostLink.Capture;

/// <summary>
/// One JSON object a line for each record:
/// <c>{"time":"2025-11-20T08:14:02.1180000Z","direction":"toPlc","unit":0,"header":"RD","frame":"@00RD0000001057*\r","durationUs":0,"flags":[]}</c>.
/// The frame is a JSON string of its bytes (a byte above 0x7F as the character of that code). Written by hand: the
/// package's netstandard2.0 build has no JSON library, and the document is six fields.
/// </summary>
internal sealed class JsonLinesCaptureWriter : CaptureWriter
{
    private readonly StringBuilder _line = new(256);

    public JsonLinesCaptureWriter(Stream file)
        : base(file)
    {
    }

    /// <summary>The name a direction has in JSON.</summary>
    public static string Name(LineDirection direction) => direction switch
    {
        LineDirection.ToPlc => "toPlc",
        LineDirection.FromPlc => "fromPlc",
        _ => "unknown",
    };

    protected override void WriteRecord(Stream file, DateTimeOffset time, LineDirection direction, ReadOnlySpan<byte> bytes, CaptureFlags flags, TimeSpan duration)
    {
        StringBuilder sb = _line.Clear();
        sb.Append("{\"time\":\"").Append(time.UtcDateTime.ToString("yyyy-MM-dd'T'HH:mm:ss.fffffff'Z'", CultureInfo.InvariantCulture)).Append('"');
        sb.Append(",\"direction\":\"").Append(Name(direction)).Append('"');
        int unit = Protocol.MessagePrefix.TryReadUnit(bytes, out int u) ? u : -1;
        sb.Append(",\"unit\":").Append(unit < 0 ? "null" : unit.ToString(CultureInfo.InvariantCulture));
        string? header = CaptureText.HeaderOf(bytes);
        sb.Append(",\"header\":");
        if (header is null)
        {
            sb.Append("null");
        }
        else
        {
            AppendString(sb, header);
        }

        sb.Append(",\"frame\":");
        var text = new char[bytes.Length];
        for (int i = 0; i < bytes.Length; i++)
        {
            text[i] = (char)bytes[i];
        }

        AppendString(sb, new string(text));
        sb.Append(",\"durationUs\":").Append((duration.Ticks / 10).ToString(CultureInfo.InvariantCulture));
        sb.Append(",\"flags\":[");
        bool first = true;
        foreach ((CaptureFlags flag, string name) in new[] { (CaptureFlags.LineError, "lineError"), (CaptureFlags.NotFramed, "notFramed") })
        {
            if ((flags & flag) != 0)
            {
                sb.Append(first ? "\"" : ",\"").Append(name).Append('"');
                first = false;
            }
        }

        sb.Append("]}\n");
        byte[] utf8 = Encoding.UTF8.GetBytes(sb.ToString());
        file.Write(utf8, 0, utf8.Length);
    }

    private static void AppendString(StringBuilder sb, string value)
    {
        sb.Append('"');
        foreach (char c in value)
        {
            switch (c)
            {
                case '"':
                    sb.Append("\\\"");
                    break;
                case '\\':
                    sb.Append("\\\\");
                    break;
                case '\r':
                    sb.Append("\\r");
                    break;
                case '\n':
                    sb.Append("\\n");
                    break;
                case < ' ' or > '~':
                    sb.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                    break;
                default:
                    sb.Append(c);
                    break;
            }
        }

        sb.Append('"');
    }
}
