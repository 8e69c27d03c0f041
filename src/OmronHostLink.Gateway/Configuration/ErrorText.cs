namespace OmronHostLink.Gateway.Configuration;

/// <summary>An exception's message in the user's words, for a start-up failure or a reply.</summary>
internal static class ErrorText
{
    /// <summary>The message without the <c>(Parameter 'x')</c> the runtime appends: the key or tag named already says which.</summary>
    public static string Of(ArgumentException e)
    {
        string message = e.Message;
        int at = e.ParamName is null ? -1 : message.LastIndexOf(" (Parameter '", StringComparison.Ordinal);
        return at >= 0 ? message.Substring(0, at) : message;
    }
}
