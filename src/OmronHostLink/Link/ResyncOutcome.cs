namespace OmronHostLink.Link;

/// <summary>What a resynchronisation achieved.</summary>
internal enum ResyncOutcome
{
    /// <summary>A TS fence was echoed: every late answer before it was discarded, and the link is in step.</summary>
    Answered,

    /// <summary>No fence was echoed within its deadline.</summary>
    Unanswered,

    /// <summary>No fence was echoed; damaged frames (leftovers of the failed exchange, or a damaged echo) were discarded.</summary>
    UnansweredAfterDamagedFrames,
}
