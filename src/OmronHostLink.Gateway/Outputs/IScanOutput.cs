namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// An output that also hears of the polling engine's scan classes: their plans and each cycle's time. The gateway's own
/// outputs (statistics, metrics) take these; <see cref="ITagOutput"/> stays the public shape an output has.
/// </summary>
internal interface IScanOutput
{
    /// <summary>A scan class was planned: at start, and again when its plan changes (a unit's model learnt, QQ refused).</summary>
    /// <param name="plan">The reads it makes each cycle.</param>
    void ScanPlanned(ScanPlan plan);

    /// <summary>A scan class read every tag once more.</summary>
    /// <param name="cycle">The cycle's time.</param>
    void ScanCycled(ScanCycle cycle);
}
