namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The <c>Quality</c> metric property: an Int32 with the OPC quality codes Ignition's MQTT Engine reads (192 good,
/// 0 bad, 500 stale). Sent only where a value is not good; a device that stops answering gets a DDEATH instead.
/// </summary>
internal static class SparkplugQuality
{
    /// <summary>The property's key.</summary>
    public const string PropertyName = "Quality";

    /// <summary>Just read.</summary>
    public const int Good = 192;

    /// <summary>No value can be given.</summary>
    public const int Bad = 0;

    /// <summary>The PLC answers but this tag could not be read; the last value stands.</summary>
    public const int Stale = 500;
}
