namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// A CSV file of tags for one unit of a link (<c>HostLink:Links:NAME:TagFiles</c>): each row becomes a poll group, as
/// if it were listed under <c>Groups</c>. See docs/tag-import.md.
/// </summary>
internal sealed class TagFileOptions
{
    /// <summary>The file; a relative path is taken from the working directory.</summary>
    public string Path { get; set; } = "";

    /// <summary><c>Kepware</c> (a KEPServerEX tag export of an Omron Host Link device, the default) or <c>Plain</c> (name,address,type,writable).</summary>
    public string Format { get; set; } = "Kepware";

    /// <summary>The PLC unit the file's tags are on, 0-31. Default 0.</summary>
    public int Unit { get; set; }

    /// <summary>The poll interval of rows that do not give one (Kepware's Scan Rate, the plain file's interval). Default 1 s.</summary>
    public TimeSpan Interval { get; set; } = TimeSpan.FromSeconds(1);

    /// <summary>EveryPoll (default) or OnChange, for every tag of the file.</summary>
    public string Log { get; set; } = nameof(PollLogMode.EveryPoll);
}
