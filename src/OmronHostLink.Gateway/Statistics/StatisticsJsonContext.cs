using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Statistics;

/// <summary>Source-generated JSON for the statistics topics.</summary>
[JsonSourceGenerationOptions(NumberHandling = JsonNumberHandling.AllowNamedFloatingPointLiterals)]
[JsonSerializable(typeof(UnitStatistics))]
[JsonSerializable(typeof(ScanClassStatistics))]
internal sealed partial class StatisticsJsonContext : JsonSerializerContext;
