namespace OmronHostLink.Cli;

/// <summary>Address arguments as the user types them.</summary>
internal static class Addresses
{
    /// <summary>Parses an address the way <see cref="PlcAddress.Parse"/> does, as a usage error when it is not valid.</summary>
    public static PlcAddress Parse(string text)
    {
        try
        {
            return PlcAddress.Parse(text);
        }
        catch (FormatException e)
        {
            throw new UsageException(e.Message, e);
        }
    }

    /// <summary>
    /// Accepts an address typed as two words (<c>CIO 100.05</c> unquoted): when <paramref name="first"/> is an area name
    /// alone and joined with <paramref name="second"/> it makes an address, the two are one address.
    /// </summary>
    /// <returns>True when the two tokens were joined.</returns>
    public static bool TryJoin(string first, string? second, out PlcAddress address)
    {
        address = default;
        return second is not null
            && first.Length > 0
            && first.All(char.IsLetter)
            && !PlcAddress.TryParse(first, out _)
            && PlcAddress.TryParse(first + " " + second, out address);
    }

    /// <summary>Checks a range against the protocol's reach, as a usage error.</summary>
    public static void EnsureRange(PlcAddress address, int words, HostLinkCommandSet protocol, bool forWrite)
    {
        try
        {
            address.EnsureRange(words, protocol, forWrite);
        }
        catch (ArgumentException e)
        {
            throw new UsageException(InCliWords(FirstSentence(e.Message)), e);
        }
    }

    /// <summary>
    /// The library's advice in the console's terms: "use FINS" (set the command set) is the option <c>--fins</c> here,
    /// and "use C-mode" is leaving it out.
    /// </summary>
    public static string InCliWords(string message) => CommandSetAdvice.Replace(message, "add --fins", "leave out --fins");

    /// <summary>An ArgumentException message without the "(Parameter 'x')" suffix.</summary>
    public static string FirstSentence(string message)
    {
        int p = message.IndexOf(" (Parameter '", StringComparison.Ordinal);
        return p > 0 ? message[..p] : message;
    }
}
