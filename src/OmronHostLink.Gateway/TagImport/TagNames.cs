namespace OmronHostLink.Gateway.TagImport;

/// <summary>What a gateway tag name may hold: it becomes an MQTT topic level and a Sparkplug metric name.</summary>
internal static class TagNames
{
    /// <summary>Why <paramref name="name"/> cannot name a tag, or null when it can.</summary>
    public static string? Check(string? name)
    {
        if (string.IsNullOrWhiteSpace(name))
        {
            return "is empty";
        }

        int bad = name.IndexOfAny(['/', '+', '#']);
        if (bad >= 0)
        {
            return $"'{name}' contains '{name[bad]}'; a tag name is one MQTT topic level, without /, + or #";
        }

        foreach (char c in name)
        {
            if (char.IsControl(c))
            {
                return $"'{name}' contains the control character U+{(int)c:X4}";
            }
        }

        return name.Length > 100 ? $"'{name.Substring(0, 20)}…' is longer than 100 characters" : null;
    }
}
