using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>Source-generated JSON for the few values the Sparkplug output turns into JSON, and the STATE it reads.</summary>
[JsonSerializable(typeof(string))]
[JsonSerializable(typeof(SparkplugStatePayload))]
internal sealed partial class SparkplugJsonContext : JsonSerializerContext;
