namespace OmronHostLink.Link;

/// <summary>How a failed attempt left the line: what the link must do before the next exchange.</summary>
internal enum AttemptFailure
{
    /// <summary>A complete error answer (an end code): the line is in step.</summary>
    InStep,

    /// <summary>Timeout, damaged frame or cancellation outside a multi-frame exchange: resynchronise.</summary>
    OutOfStep,

    /// <summary>The failure cut a multi-frame exchange: initialise the line, then resynchronise.</summary>
    Cut,

    /// <summary>The stream failed: break the link.</summary>
    Lost,
}
