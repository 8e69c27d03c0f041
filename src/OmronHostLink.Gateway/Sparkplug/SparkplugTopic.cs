namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// A Sparkplug B topic: <c>spBv1.0/group_id/message_type/edge_node_id[/device_id]</c> (specification 3.0, 4.1).
/// </summary>
/// <param name="GroupId">The group the edge node belongs to.</param>
/// <param name="Type">The message type.</param>
/// <param name="EdgeNodeId">The edge node (this gateway).</param>
/// <param name="DeviceId">The device (a PLC unit); null for node messages.</param>
internal sealed record SparkplugTopic(string GroupId, SparkplugMessageType Type, string EdgeNodeId, string? DeviceId = null)
{
    /// <summary>The namespace element every Sparkplug B topic starts with.</summary>
    public const string Namespace = "spBv1.0";

    /// <summary>The topic text.</summary>
    public override string ToString()
        => DeviceId is null
            ? $"{Namespace}/{GroupId}/{Type}/{EdgeNodeId}"
            : $"{Namespace}/{GroupId}/{Type}/{EdgeNodeId}/{DeviceId}";

    /// <summary>Reads a topic; false for anything that is not a Sparkplug B node or device topic.</summary>
    public static bool TryParse(string topic, out SparkplugTopic? parsed)
    {
        parsed = null;
        string[] parts = topic.Split('/');
        if (parts.Length is not (4 or 5) || parts[0] != Namespace
            || !Enum.TryParse(parts[2], ignoreCase: false, out SparkplugMessageType type) || type == SparkplugMessageType.STATE
            || parts[2] != type.ToString())
        {
            return false;
        }

        foreach (string part in parts)
        {
            if (part.Length == 0)
            {
                return false;
            }
        }

        parsed = new SparkplugTopic(parts[1], type, parts[3], parts.Length == 5 ? parts[4] : null);
        return true;
    }

    /// <summary>
    /// Why <paramref name="id"/> cannot be a group, edge node or device id, or null when it can: the specification
    /// allows any UTF-8 text without the MQTT separators and wildcards <c>/</c>, <c>+</c> and <c>#</c>.
    /// </summary>
    public static string? Check(string? id)
    {
        if (string.IsNullOrWhiteSpace(id))
        {
            return "it is empty";
        }

        int bad = id.IndexOfAny(['/', '+', '#']);
        if (bad >= 0)
        {
            return $"it contains '{id[bad]}', which a Sparkplug id cannot hold (/, + and # are MQTT topic separators and wildcards)";
        }

        foreach (char c in id)
        {
            if (char.IsControl(c))
            {
                return $"it contains the control character U+{(int)c:X4}";
            }
        }

        return null;
    }
}
