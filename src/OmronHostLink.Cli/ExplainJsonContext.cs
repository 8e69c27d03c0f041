using System.Text.Json;
using System.Text.Json.Serialization;
using System.Text.Json.Serialization.Metadata;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli;

/// <summary>
/// The JSON of <c>explain</c>, generated at compile time from <see cref="FrameExplanation"/>. The field values a frame's
/// fields hold are listed so that <see cref="object"/> values serialise without reflection.
/// </summary>
[JsonSourceGenerationOptions(PropertyNamingPolicy = JsonKnownNamingPolicy.CamelCase)]
[JsonSerializable(typeof(FrameExplanation))]
[JsonSerializable(typeof(string))]
[JsonSerializable(typeof(long))]
[JsonSerializable(typeof(bool))]
[JsonSerializable(typeof(string[]))]
[JsonSerializable(typeof(long[]))]
[JsonSerializable(typeof(bool[]))]
[JsonSerializable(typeof(FinsAddressField))]
[JsonSerializable(typeof(FinsAddressField[]))]
internal sealed partial class ExplainJsonContext : JsonSerializerContext
{
    private static JsonSerializerOptions? s_explanationOptions;

    /// <summary>Options over the generated contract (made on first use, after <see cref="Default"/>); <c>data</c> belongs to answers only.</summary>
    private static JsonSerializerOptions ExplanationOptions => s_explanationOptions ??= new()
    {
        PropertyNamingPolicy = JsonNamingPolicy.CamelCase,
        TypeInfoResolver = JsonTypeInfoResolver.WithAddedModifier(Default, static info =>
        {
            if (info.Type == typeof(FinsAddressField))
            {
                // A plain address has no action: the field is left out rather than written as null.
                foreach (JsonPropertyInfo property in info.Properties)
                {
                    if (property.Name == "action")
                    {
                        property.ShouldSerialize = static (_, value) => value is not null;
                    }
                }

                return;
            }

            if (info.Type != typeof(FrameExplanation))
            {
                return;
            }

            foreach (JsonPropertyInfo property in info.Properties)
            {
                if (property.Name == "data")
                {
                    property.ShouldSerialize = static (owner, _) => ((FrameExplanation)owner).IsResponse;
                }
            }
        }),
    };

    /// <summary>Writes <paramref name="explanation"/> as one JSON document.</summary>
    public static void Write(Utf8JsonWriter writer, FrameExplanation explanation)
        => JsonSerializer.Serialize(writer, explanation, (JsonTypeInfo<FrameExplanation>)ExplanationOptions.GetTypeInfo(typeof(FrameExplanation)));
}
