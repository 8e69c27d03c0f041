using System.Text.Json;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The primary host application as the edge node knows it from the STATE messages on <see cref="Topic"/> (specification
/// 3.0): online for the current connection once a STATE on it says so; offline again when a STATE says so. A STATE whose
/// timestamp is older than the last one taken is ignored (the late will of a host session already replaced); the first
/// one is always taken. A legacy host (Sparkplug 2.2) publishes <c>STATE/{id}</c> with the plain text <c>ONLINE</c> or
/// <c>OFFLINE</c> and no timestamp: every such STATE is taken. Thread-safe: STATE messages arrive on the client's
/// thread, the publisher reads.
/// </summary>
/// <param name="hostId">The primary host application's id (<see cref="SparkplugOptions.PrimaryHostId"/>).</param>
/// <param name="legacy">The host speaks Sparkplug 2.2's STATE (<see cref="SparkplugOptions.PrimaryHostLegacyState"/>).</param>
internal sealed class SparkplugPrimaryHost(string hostId, bool legacy = false)
{
    private const string LegacyOnline = "ONLINE";
    private const string LegacyOffline = "OFFLINE";

    private readonly object _gate = new();
    private long? _timestamp;
    private bool _online;
    private bool _heard;

    /// <summary>The host application's id.</summary>
    public string HostId { get; } = hostId;

    /// <summary>Whether the host speaks Sparkplug 2.2's STATE.</summary>
    public bool Legacy { get; } = legacy;

    /// <summary>The host application's STATE topic: <c>spBv1.0/STATE/{HostId}</c>, or <c>STATE/{HostId}</c> for a legacy host.</summary>
    public string Topic { get; } = legacy ? $"{SparkplugMessageType.STATE}/{hostId}" : $"{SparkplugTopic.Namespace}/{SparkplugMessageType.STATE}/{hostId}";

    /// <summary>Whether a STATE has been taken on the current connection (the retained one comes first).</summary>
    public bool Heard
    {
        get
        {
            lock (_gate)
            {
                return _heard;
            }
        }
    }

    /// <summary>Whether the last STATE taken on this connection says online.</summary>
    public bool IsOnline
    {
        get
        {
            lock (_gate)
            {
                return _online;
            }
        }
    }

    /// <summary>The timestamp of the last STATE taken (milliseconds since the Unix epoch); null before the first.</summary>
    public long? Timestamp
    {
        get
        {
            lock (_gate)
            {
                return _timestamp;
            }
        }
    }

    /// <summary>
    /// A new connection is being made: the host counts as offline until a STATE on it (the retained one first) says
    /// online. The last timestamp is kept, so that a STATE older than one already taken is still ignored.
    /// </summary>
    public void Connecting()
    {
        lock (_gate)
        {
            _online = false;
            _heard = false;
        }
    }

    /// <summary>Takes a STATE payload.</summary>
    /// <returns>Null when it is taken; otherwise why it is ignored.</returns>
    public string? Take(ReadOnlySpan<byte> payload)
    {
        string text = System.Text.Encoding.UTF8.GetString(payload).Trim();
        if (Legacy)
        {
            if (text is not (LegacyOnline or LegacyOffline))
            {
                return $"the payload is not ONLINE or OFFLINE, the STATE of Sparkplug 2.2 (Sparkplug:PrimaryHostLegacyState is on)";
            }

            lock (_gate)
            {
                _online = text == LegacyOnline;
                _heard = true;
                return null;
            }
        }

        if (text is LegacyOnline or LegacyOffline)
        {
            return $"'{text}' is the STATE of Sparkplug 2.2, not the JSON {{\"online\": true or false, \"timestamp\": milliseconds since 1970}} of Sparkplug 3.0; for such a host set Sparkplug:PrimaryHostLegacyState to true (and it publishes on STATE/{HostId}, not on {Topic})";
        }

        SparkplugStatePayload? state;
        try
        {
            state = JsonSerializer.Deserialize(payload, SparkplugJsonContext.Default.SparkplugStatePayload);
        }
        catch (JsonException)
        {
            state = null;
        }

        if (state is not { Online: { } online, Timestamp: { } timestamp })
        {
            return "the payload is not the JSON {\"online\": true or false, \"timestamp\": milliseconds since 1970} of Sparkplug 3.0";
        }

        lock (_gate)
        {
            if (timestamp < _timestamp)
            {
                return $"its timestamp {timestamp} is older than that of the last STATE taken, {_timestamp}";
            }

            _timestamp = timestamp;
            _online = online;
            _heard = true;
            return null;
        }
    }
}
