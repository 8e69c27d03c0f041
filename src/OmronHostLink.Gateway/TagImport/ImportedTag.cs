namespace OmronHostLink.Gateway.TagImport;

/// <summary>A tag read from an import file, translated to the gateway's terms.</summary>
/// <param name="Line">The line of the file it came from.</param>
/// <param name="Name">The tag's name.</param>
/// <param name="Address">Its first address, in the core's spelling (<see cref="PlcAddress.ToString"/>).</param>
/// <param name="Type">How its words are read.</param>
/// <param name="Count">How many values (characters for a string).</param>
/// <param name="Writable">Whether the file allows writes to it.</param>
/// <param name="Interval">How often to poll it, when the file says (Kepware's scan rate); null for the default.</param>
/// <param name="Description">The file's description of it, if any.</param>
internal sealed record ImportedTag(int Line, string Name, string Address, PlcValueType Type, int Count, bool Writable, TimeSpan? Interval = null, string? Description = null);
