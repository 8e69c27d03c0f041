namespace OmronHostLink.Gateway.Outputs;

/// <summary>One cycle of a scan class: every tag of one unit at one interval read.</summary>
/// <param name="Link">The link's configured name.</param>
/// <param name="Unit">The PLC's unit number, 0–31.</param>
/// <param name="Interval">The scan class's interval.</param>
/// <param name="Duration">The cycle's time, from its start to its last answer (waits for the line included).</param>
/// <param name="Overran">Whether it started late: the cycle before it ended after this one was due.</param>
internal sealed record ScanCycle(string Link, int Unit, TimeSpan Interval, TimeSpan Duration, bool Overran);
