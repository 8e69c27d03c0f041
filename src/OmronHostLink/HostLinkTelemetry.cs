namespace OmronHostLink;

/// <summary>
/// The names under which the library publishes its metrics and traces, for OpenTelemetry
/// (<c>.AddMeter(HostLinkTelemetry.MeterName)</c>, <c>.AddSource(HostLinkTelemetry.ActivitySourceName)</c>) and
/// <c>dotnet-counters monitor --counters OmronHostLink</c>.
/// </summary>
/// <remarks>
/// <para>Metrics (meter <see cref="MeterName"/>, made through <see cref="HostLinkClientOptions.MeterFactory"/> when one
/// is given, else one shared static meter):</para>
/// <list type="bullet">
/// <item><c>hostlink.client.operation.duration</c> (histogram, seconds): each command from the call to its answer or
/// final error, waiting for the line, resynchronisation and retries included; <c>error.type</c> on failures.</item>
/// <item><c>hostlink.client.exchange.duration</c> (histogram, seconds): the answered attempt of each command that
/// succeeded, from its first frame sent to the last frame of the answer: the PLC's response time on the line,
/// without the wait for the line, resynchronisation or failed attempts.</item>
/// <item><c>hostlink.client.retries</c> (counter): attempts repeated after a timeout or damaged frame, by the
/// <c>error.type</c> of the attempt that failed.</item>
/// <item><c>hostlink.client.connection.count</c> (observable up/down counter): links whose transport is open, as
/// observed at each collection.</item>
/// </list>
/// <para>Every measurement carries <c>hostlink.link.name</c> (<see cref="HostLinkClientOptions.LinkName"/>); the
/// operation instruments also <c>hostlink.unit</c> and <c>hostlink.command</c> (the header: <c>RD</c>, <c>FA</c>…).</para>
/// <para>Traces (activity source <see cref="ActivitySourceName"/>): one client span per command, not per attempt,
/// started only when a listener samples it.</para>
/// </remarks>
public static class HostLinkTelemetry
{
    /// <summary>The meter's name: <c>OmronHostLink</c>.</summary>
    public const string MeterName = "OmronHostLink";

    /// <summary>The activity source's name: <c>OmronHostLink</c>.</summary>
    public const string ActivitySourceName = "OmronHostLink";
}
