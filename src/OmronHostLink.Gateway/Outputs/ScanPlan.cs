namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// The reads one scan class makes each cycle — the poll groups of one unit at one interval, planned together — and the
/// time they take at the line's speed.
/// </summary>
/// <param name="Link">The link's configured name.</param>
/// <param name="Unit">The PLC's unit number, 0–31.</param>
/// <param name="Interval">The scan class's interval.</param>
/// <param name="Tags">The poll groups (tags) read.</param>
/// <param name="Reads">The commands a cycle.</param>
/// <param name="Characters">The characters on the line a cycle, both ways.</param>
/// <param name="EstimatedCycle">The least time a cycle takes on the line: its characters at the line's speed, and the send interval before each command.</param>
/// <param name="Description">The plan in words: <c>5 reads (1 QQIR of 120 items, 3 C-mode area reads, 1 C-mode RG read), 806 characters, 924 ms at 9600 bps</c>.</param>
internal sealed record ScanPlan(string Link, int Unit, TimeSpan Interval, int Tags, int Reads, int Characters, TimeSpan EstimatedCycle, string Description);
