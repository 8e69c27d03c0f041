namespace OmronHostLink.Gateway.Writes;

/// <summary>What became of a write.</summary>
internal enum TagWriteStatus
{
    /// <summary>The PLC took the value (end code 00).</summary>
    Done,

    /// <summary>Refused before anything reached the wire.</summary>
    Refused,

    /// <summary>The PLC refused the write (an end code), or it did not complete (a timeout, a lost link).</summary>
    Failed,
}

/// <summary>The names replies and metrics give a <see cref="TagWriteStatus"/>.</summary>
internal static class TagWriteStatusNames
{
    /// <summary><c>done</c>, <c>refused</c> or <c>failed</c>.</summary>
    public static string Name(this TagWriteStatus status) => status switch
    {
        TagWriteStatus.Done => "done",
        TagWriteStatus.Refused => "refused",
        _ => "failed",
    };
}
