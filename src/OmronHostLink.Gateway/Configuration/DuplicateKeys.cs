using System.Globalization;
using System.Text.Json;
using Microsoft.Extensions.Configuration;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// Where a JSON configuration file gives a key twice. The configuration's JSON reader names the key (as a path, such as
/// <c>HostLink:Links:plc:Groups:levels:Address</c>) but not its lines; this reads the file again to find them.
/// </summary>
internal static class DuplicateKeys
{
    /// <summary>The lines (1-based) of the first two occurrences of <paramref name="key"/> (compared ignoring case, as the configuration does) in the JSON file <paramref name="path"/>; null if it cannot tell.</summary>
    public static (int First, int Second)? Lines(string path, string key)
    {
        byte[] bytes;
        try
        {
            bytes = File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }

        ReadOnlySpan<byte> json = bytes.AsSpan();
        int offset = json.StartsWith("\uFEFF"u8) ? 3 : 0;
        var reader = new Utf8JsonReader(json.Slice(offset), new JsonReaderOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
        var containers = new Stack<Container>();
        string? property = null;
        int? first = null;
        try
        {
            while (reader.Read())
            {
                switch (reader.TokenType)
                {
                    case JsonTokenType.PropertyName:
                        property = reader.GetString();
                        break;
                    case JsonTokenType.StartObject or JsonTokenType.StartArray:
                        containers.Push(new Container(containers.Count == 0 ? "" : ChildPath(containers, property), reader.TokenType == JsonTokenType.StartArray));
                        break;
                    case JsonTokenType.EndObject or JsonTokenType.EndArray:
                        containers.Pop();
                        break;
                    default:
                        if (containers.Count > 0 && string.Equals(ChildPath(containers, property), key, StringComparison.OrdinalIgnoreCase))
                        {
                            int line = 1 + json.Slice(0, offset + (int)reader.TokenStartIndex).Count((byte)'\n');
                            if (first is { } earlier)
                            {
                                return (earlier, line);
                            }

                            first = line;
                        }

                        break;
                }
            }
        }
        catch (JsonException)
        {
        }

        return null;
    }

    private static string ChildPath(Stack<Container> containers, string? property)
    {
        Container parent = containers.Peek();
        string name = parent.IsArray ? (parent.Items++).ToString(CultureInfo.InvariantCulture) : property ?? "";
        return parent.Path.Length == 0 ? name : parent.Path + ConfigurationPath.KeyDelimiter + name;
    }

    private sealed class Container(string path, bool isArray)
    {
        public string Path { get; } = path;

        public bool IsArray { get; } = isArray;

        public int Items { get; set; }
    }
}
