using System.Globalization;
using System.Text.Json;
using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Outputs;

/// <summary>Writes times as ISO 8601 UTC with milliseconds (<c>2025-01-31T08:00:00.125Z</c>): one fixed width for every consumer.</summary>
internal sealed class UtcTimeJsonConverter : JsonConverter<DateTimeOffset?>
{
    /// <summary>The format written.</summary>
    public const string Format = "yyyy-MM-dd'T'HH:mm:ss.fff'Z'";

    /// <inheritdoc/>
    public override bool HandleNull => true;

    /// <inheritdoc/>
    public override DateTimeOffset? Read(ref Utf8JsonReader reader, Type typeToConvert, JsonSerializerOptions options)
        => reader.TokenType == JsonTokenType.Null ? null : reader.GetDateTimeOffset();

    /// <inheritdoc/>
    public override void Write(Utf8JsonWriter writer, DateTimeOffset? value, JsonSerializerOptions options)
    {
        ArgumentNullException.ThrowIfNull(writer);
        if (value is { } time)
        {
            writer.WriteStringValue(time.UtcDateTime.ToString(Format, CultureInfo.InvariantCulture));
        }
        else
        {
            writer.WriteNullValue();
        }
    }
}
