using System.Text.Encodings.Web;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.Json.Serialization;

namespace OmronHostLink.Cli;

/// <summary><c>{"error":{…}}</c>: what <c>--json</c> prints on stdout when a command fails.</summary>
internal sealed record ErrorDocument(ErrorInfo Error);

/// <summary>Why a command failed.</summary>
/// <param name="Kind"><c>endCode</c>, <c>timeout</c>, <c>frame</c>, <c>connection</c>, <c>usage</c>, <c>cancelled</c> or <c>other</c>.</param>
/// <param name="EndCode">The PLC's end code (two hex digits for C-mode, four for FINS) when <paramref name="Kind"/> is <c>endCode</c>; otherwise null.</param>
/// <param name="Message">The sentence also printed on stderr.</param>
internal sealed record ErrorInfo(string Kind, string? EndCode, string Message);

/// <summary>What <c>write --json</c> prints: where, what was written (as values and, for word writes, as words), and that the PLC accepted it.</summary>
internal sealed record WriteDocument(int Unit, string Address, string As, JsonArray Values, ushort[]? Words, bool Ok);

/// <summary>A <c>monitor --json</c> line about the link rather than values: the watch lost or regained the PLC, or a poll overran the interval.</summary>
/// <param name="Time">When it happened.</param>
/// <param name="Status"><c>lost</c>, <c>resumed</c> or <c>overrun</c>.</param>
/// <param name="Unit">The unit polled.</param>
/// <param name="Kind">For <c>lost</c>: the failure's kind, as in <see cref="ErrorInfo.Kind"/>.</param>
/// <param name="Message">For <c>lost</c>: what failed; for <c>resumed</c>: how long the outage lasted; for <c>overrun</c>: how long the poll took.</param>
internal sealed record MonitorStatusDocument(DateTimeOffset Time, string Status, int Unit, string? Kind, string Message);

/// <summary>Source-generated serialisation of the console's JSON documents (no reflection).</summary>
[JsonSourceGenerationOptions(PropertyNamingPolicy = JsonKnownNamingPolicy.CamelCase)]
[JsonSerializable(typeof(ErrorDocument))]
[JsonSerializable(typeof(ErrorInfo))]
[JsonSerializable(typeof(WriteDocument))]
[JsonSerializable(typeof(MonitorStatusDocument))]
internal sealed partial class CliJsonContext : JsonSerializerContext
{
    /// <summary>Compact, camelCase, and readable in a console (quotes and apostrophes are not escaped).</summary>
    public static CliJsonContext Console { get; } = new(new JsonSerializerOptions
    {
        PropertyNamingPolicy = JsonNamingPolicy.CamelCase,
        Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
        WriteIndented = false,
    });
}
