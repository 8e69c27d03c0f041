using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Detection;

/// <summary>One TS probe at one speed and format: what was sent, what came back, and how long it took.</summary>
/// <param name="Baud">The speed tried.</param>
/// <param name="Format">The format tried.</param>
/// <param name="Unit">The unit number the TS went to.</param>
/// <param name="Sent">The frame sent.</param>
/// <param name="Reply">What came back.</param>
/// <param name="Elapsed">From sending to giving up or taking the answer.</param>
/// <param name="RoundTrip">From sending to the answer, when one came.</param>
/// <param name="Confirming">Whether this try only checked whether the line echoes (a copy of our frame came at another format too).</param>
internal sealed record ProbeTry(int Baud, LineFormat Format, int Unit, byte[] Sent, ProbeReply Reply, TimeSpan Elapsed, TimeSpan? RoundTrip, bool Confirming = false)
{
    /// <summary>"19200 8N1".</summary>
    public string Settings => $"{Baud} {Format}";

    /// <summary>The port settings of this try.</summary>
    public SerialLineSettings At(string port) => Format.At(port, Baud);
}
