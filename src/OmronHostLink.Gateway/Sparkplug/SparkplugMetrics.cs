using System.Diagnostics.Metrics;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The edge node's instruments on the gateway's meter, read from the node: births published, rebirths asked for, and
/// store-and-forward (changes kept now, published as history, dropped).
/// </summary>
internal static class SparkplugMetrics
{
    /// <summary>Creates the instruments, observing <paramref name="node"/>.</summary>
    public static void Create(IMeterFactory meterFactory, SparkplugNode node)
    {
        ArgumentNullException.ThrowIfNull(meterFactory);
        ArgumentNullException.ThrowIfNull(node);
        Meter meter = meterFactory.Create(GatewayNames.Meter);
        meter.CreateObservableCounter("hostlink.gateway.sparkplug.births", () => node.BirthsPublished, "{message}", "NBIRTH and DBIRTH messages published.");
        meter.CreateObservableCounter("hostlink.gateway.sparkplug.rebirth_requests", () => node.RebirthsRequested, "{request}", "Rebirths host applications asked for (NCMD Node Control/Rebirth).");
        meter.CreateObservableGauge("hostlink.gateway.sparkplug.store.length", () => node.Store.Stored, "{change}", "Changes kept by store-and-forward, waiting to be published as history.");
        meter.CreateObservableCounter("hostlink.gateway.sparkplug.store.sent", () => node.Store.Sent, "{change}", "Stored changes published as history (is_historical).");
        meter.CreateObservableCounter("hostlink.gateway.sparkplug.store.dropped", () => node.Store.Dropped, "{change}", "Changes store-and-forward dropped: over its bounds, too old, or lost with a run that kept them in memory.");
    }
}
