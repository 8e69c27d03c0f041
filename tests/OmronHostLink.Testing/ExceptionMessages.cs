namespace OmronHostLink.Testing;

/// <summary>Every message of an exception and the exceptions inside it (aggregates flattened), outermost first.</summary>
public static class ExceptionMessages
{
    /// <summary>The messages of <paramref name="e"/>, its inner exceptions and an aggregate's exceptions.</summary>
    public static IEnumerable<string> Of(Exception e)
    {
        ArgumentNullException.ThrowIfNull(e);
        return e is AggregateException a
            ? a.InnerExceptions.SelectMany(Of).Prepend(e.Message)
            : e.InnerException is null ? [e.Message] : Of(e.InnerException).Prepend(e.Message);
    }
}
