namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>A message the edge node publishes: its topic and payload.</summary>
/// <param name="Topic">The Sparkplug topic.</param>
/// <param name="Payload">The encoded payload.</param>
internal sealed record SparkplugMessage(SparkplugTopic Topic, byte[] Payload);
