namespace OmronHostLink.Gateway.Mqtt;

/// <summary>A write command as received: copied out of the MQTT client's buffers so it can wait its turn.</summary>
/// <param name="Topic">The command topic, <c>{prefix}/{link}/{unit}/{tag}/set</c>.</param>
/// <param name="Payload">The JSON value, bare (<c>1234</c>) or as <c>{"value":1234}</c>.</param>
/// <param name="ResponseTopic">The MQTT 5 response topic, if the sender gave one.</param>
/// <param name="CorrelationData">The MQTT 5 correlation data, if the sender gave it.</param>
/// <param name="Retained">Whether the broker delivered it from its retained store.</param>
internal sealed record WriteCommand(string Topic, byte[] Payload, string? ResponseTopic, byte[]? CorrelationData, bool Retained);
