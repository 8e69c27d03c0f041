namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// One metric of a device as its birth declares it: a tag of one value, or one element of a tag of several
/// (<c>name/0</c>, <c>name/1</c>…, which Ignition shows as a folder).
/// </summary>
/// <param name="Name">The metric name.</param>
/// <param name="Alias">Its alias, unique within the edge node.</param>
/// <param name="DataType">Its Sparkplug data type.</param>
/// <param name="Tag">The tag it belongs to.</param>
/// <param name="Element">The element of the tag's values; -1 for a tag of one value.</param>
/// <param name="Writable">Whether a DCMD may write it (the tag is on the write allowlist).</param>
internal sealed record SparkplugMetric(string Name, ulong Alias, SparkplugDataType DataType, string Tag, int Element, bool Writable);
