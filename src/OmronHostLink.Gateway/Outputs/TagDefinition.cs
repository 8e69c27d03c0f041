namespace OmronHostLink.Gateway.Outputs;

/// <summary>A tag (a poll group) as the MQTT output knows it: where it is, how it is read, whether it may be written.</summary>
/// <param name="Link">The link's configured name.</param>
/// <param name="Unit">The PLC unit number.</param>
/// <param name="Name">The tag's (poll group's) name.</param>
/// <param name="Address">The first address.</param>
/// <param name="Type">How the words are read.</param>
/// <param name="Count">How many values (characters for <c>string</c>, bits for <c>bit</c>).</param>
/// <param name="WordOrder">Word order of 32-bit values on the link.</param>
/// <param name="Writable">Listed as writable in configuration.</param>
/// <param name="CommandSet">The link's command set (what it can write depends on it).</param>
internal sealed record TagDefinition(string Link, int Unit, string Name, PlcAddress Address, PlcValueType Type, int Count, WordOrder WordOrder, bool Writable, HostLinkCommandSet CommandSet);
