using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// Source-generated JSON for the MQTT payloads (serialize through <see cref="MqttJson"/>). The value types of <see cref="Outputs.TagValues"/> are listed so a
/// value held as <see cref="object"/> serialises without reflection. A REAL that is NaN or infinite is written as the
/// string <c>"NaN"</c>, <c>"Infinity"</c> or <c>"-Infinity"</c> (JSON has no such numbers).
/// </summary>
[JsonSourceGenerationOptions(
    PropertyNamingPolicy = JsonKnownNamingPolicy.CamelCase,
    DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingNull,
    NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals)]
[JsonSerializable(typeof(TagPayload))]
[JsonSerializable(typeof(WriteResultPayload))]
[JsonSerializable(typeof(LostMessagesPayload))]
[JsonSerializable(typeof(OutputsPayload))]
[JsonSerializable(typeof(ushort))]
[JsonSerializable(typeof(short))]
[JsonSerializable(typeof(int))]
[JsonSerializable(typeof(uint))]
[JsonSerializable(typeof(float))]
[JsonSerializable(typeof(double))]
[JsonSerializable(typeof(string))]
[JsonSerializable(typeof(bool))]
[JsonSerializable(typeof(ushort[]))]
[JsonSerializable(typeof(short[]))]
[JsonSerializable(typeof(int[]))]
[JsonSerializable(typeof(uint[]))]
[JsonSerializable(typeof(float[]))]
[JsonSerializable(typeof(double[]))]
[JsonSerializable(typeof(bool[]))]
internal sealed partial class MqttJsonContext : JsonSerializerContext;
