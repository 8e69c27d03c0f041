namespace OmronHostLink;

/// <summary>A client setting that cannot be used, and why, in the words of the person who wrote it.</summary>
public sealed class HostLinkSettingsProblem
{
    /// <summary>Creates a problem.</summary>
    /// <param name="key">The key path below the client's section, such as <c>Serial:BaudRate</c>; empty for the section itself.</param>
    /// <param name="message">What is wrong and what to write instead.</param>
    public HostLinkSettingsProblem(string key, string message)
    {
        Key = Guard.NotNull(key);
        Message = Guard.NotNull(message);
    }

    /// <summary>The key path below the client's section, such as <c>Serial:BaudRate</c>; empty for the section itself.</summary>
    public string Key { get; }

    /// <summary>What is wrong and what to write instead, such as <c>12345 is not a standard rate (…)</c>.</summary>
    public string Message { get; }

    /// <summary>True when this problem is at <paramref name="key"/> or inside it.</summary>
    internal bool IsAtOrBelow(string key)
        => Key.Equals(key, StringComparison.OrdinalIgnoreCase)
        || (Key.Length > key.Length && Key[key.Length] == ':' && Key.StartsWith(key, StringComparison.OrdinalIgnoreCase));

    /// <summary><c>Serial:BaudRate: 12345 is not a standard rate (…)</c>.</summary>
    /// <returns>The key and the message.</returns>
    public override string ToString() => Key.Length == 0 ? Message : $"{Key}: {Message}";
}
