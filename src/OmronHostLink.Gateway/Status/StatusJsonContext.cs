using System.Text.Json.Serialization;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// Source-generated JSON for the page's documents. The value types of a tag are listed so that a value held as
/// <see cref="object"/> serialises without reflection; a REAL that is NaN or infinite is written as a string.
/// </summary>
[JsonSourceGenerationOptions(
    PropertyNamingPolicy = JsonKnownNamingPolicy.CamelCase,
    DefaultIgnoreCondition = JsonIgnoreCondition.WhenWritingNull,
    NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals)]
[JsonSerializable(typeof(LinesDocument))]
[JsonSerializable(typeof(TagsDocument))]
[JsonSerializable(typeof(OutputsDocument))]
[JsonSerializable(typeof(OutputStatus))]
[JsonSerializable(typeof(TraceDocument))]
[JsonSerializable(typeof(IReadOnlyList<string>))]
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
internal sealed partial class StatusJsonContext : JsonSerializerContext;
