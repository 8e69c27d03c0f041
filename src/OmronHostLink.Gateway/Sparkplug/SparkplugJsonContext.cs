using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>Source-generated JSON for the few values the Sparkplug output turns into JSON.</summary>
[JsonSerializable(typeof(string))]
internal sealed partial class SparkplugJsonContext : JsonSerializerContext;
