namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// The reads one scan class makes each cycle — the poll groups of one unit at one interval, planned together — the
/// time they take at the line's speed, and the cycle the class can expect on the line it shares with the link's others.
/// </summary>
/// <param name="Link">The link's configured name.</param>
/// <param name="Unit">The PLC's unit number, 0–31.</param>
/// <param name="Interval">The scan class's interval.</param>
/// <param name="Tags">The poll groups (tags) read.</param>
/// <param name="Reads">The commands a cycle.</param>
/// <param name="Characters">The characters on the line a cycle, both ways.</param>
/// <param name="LineTime">The class's own time on the line a cycle: its characters at the line's speed, and the send interval before each command.</param>
/// <param name="EstimatedCycle">The cycle the class can expect, from its start to its last answer: its own time on the line and its waits for the reads of the link's other classes (as the link's line schedule runs them); its own time when it is alone on the line.</param>
/// <param name="Description">The plan in words: <c>5 reads (1 QQIR of 120 items, 3 C-mode area reads, 1 C-mode RG read), 806 characters, 924 ms at 9600 bps</c>.</param>
internal sealed record ScanPlan(string Link, int Unit, TimeSpan Interval, int Tags, int Reads, int Characters, TimeSpan LineTime, TimeSpan EstimatedCycle, string Description);
