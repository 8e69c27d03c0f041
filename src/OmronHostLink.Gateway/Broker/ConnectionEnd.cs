namespace OmronHostLink.Gateway.Broker;

/// <summary>How a connection attempt failed or a connection ended, and what the connection does next.</summary>
/// <param name="Server">The server it failed or ended on.</param>
/// <param name="Reason">Why, in a few words.</param>
/// <param name="Delay">How long to wait before the next attempt (zero when the next server is tried at once).</param>
/// <param name="Next">The server tried next (the same one when the list has one).</param>
/// <param name="WasConnected">True for a connection that ended; false for an attempt that failed.</param>
/// <param name="FirstFailure">True for the first failure since the last connection (an outage starts: worth a warning).</param>
/// <param name="DuplicateIdentity">
/// Another client is taking this client id's sessions over (said once as an error already): a lost connection is no news.
/// </param>
internal sealed record ConnectionEnd(MqttServer Server, string Reason, TimeSpan Delay, MqttServer Next, bool WasConnected, bool FirstFailure, bool DuplicateIdentity = false)
{
    /// <summary>What happened, for a log: <c>not reachable</c> for an attempt, <c>connection lost</c> for a connection.</summary>
    public string Problem => WasConnected ? "connection lost" : "not reachable";

    /// <summary>Whether it is worth a warning: the first failure of an outage, unless a duplicate client id explains it.</summary>
    public bool Warn => FirstFailure && !DuplicateIdentity;

    /// <summary>What the connection does next, for a log: <c>trying 127.0.0.1:1884 (Mqtt:Servers:1) at once</c>, or <c>retrying in 2 s</c>.</summary>
    public string NextStep
        => Next.Index != Server.Index
            ? Delay == TimeSpan.Zero ? $"trying {Next} at once" : $"trying {Next} in {Delay.TotalSeconds:0.###} s"
            : $"retrying in {Delay.TotalSeconds:0.###} s";
}
