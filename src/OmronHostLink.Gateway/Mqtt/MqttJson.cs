using System.Text.Encodings.Web;
using System.Text.Json;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The serializer context of every MQTT payload: <see cref="MqttJsonContext"/> with an encoder that escapes only what
/// JSON requires, so that a reply reads <c>"without \"value\""</c> and <c>'T5'</c> rather than <c>\u0022</c> and
/// <c>\u0027</c> (the default encoder escapes for embedding in HTML, which an MQTT payload never is).
/// </summary>
internal static class MqttJson
{
    /// <summary>The context to serialize with.</summary>
    public static MqttJsonContext Context { get; } = new(new JsonSerializerOptions(MqttJsonContext.Default.Options)
    {
        TypeInfoResolver = null,
        Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
    });
}
