namespace OmronHostLink.DependencyInjection.Configuration;

/// <summary>A setting that cannot be used, and why, in the words of the person who wrote it.</summary>
internal sealed class SettingsProblem
{
    public SettingsProblem(string key, string message)
    {
        Key = key;
        Message = message;
    }

    /// <summary>The key below the client's section, such as <c>Serial:BaudRate</c>; empty for the section itself.</summary>
    public string Key { get; }

    /// <summary>What is wrong and what to write instead.</summary>
    public string Message { get; }

    /// <summary>True when this problem is at <paramref name="key"/> or inside it.</summary>
    public bool IsAtOrBelow(string key)
        => Key.Equals(key, StringComparison.OrdinalIgnoreCase)
        || (Key.Length > key.Length && Key[key.Length] == ':' && Key.StartsWith(key, StringComparison.OrdinalIgnoreCase));
}
