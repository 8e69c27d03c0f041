namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>The Sparkplug B message types (the third topic level), as the specification spells them.</summary>
internal enum SparkplugMessageType
{
    /// <summary>The edge node is online: its metrics, with aliases, and a new <c>bdSeq</c>.</summary>
    NBIRTH,

    /// <summary>The edge node is offline: its MQTT will, carrying the <c>bdSeq</c> of the birth it ends.</summary>
    NDEATH,

    /// <summary>A device (a PLC unit) is online: every metric with name, alias, type and value.</summary>
    DBIRTH,

    /// <summary>A device is offline: its metrics are stale until its next birth.</summary>
    DDEATH,

    /// <summary>Edge-node metrics that changed.</summary>
    NDATA,

    /// <summary>Device metrics that changed, by alias.</summary>
    DDATA,

    /// <summary>A command to the edge node (<c>Node Control/Rebirth</c>).</summary>
    NCMD,

    /// <summary>A command to a device: metric writes.</summary>
    DCMD,

    /// <summary>A host application's online state (<c>spBv1.0/STATE/host_id</c>); not sent by edge nodes.</summary>
    STATE,
}
