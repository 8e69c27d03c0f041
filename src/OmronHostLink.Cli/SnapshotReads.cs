namespace OmronHostLink.Cli;

/// <summary>How <c>read</c> and <c>monitor</c> take a snapshot: each read is one command.</summary>
internal static class SnapshotReads
{
    /// <summary>
    /// Reads the values of <paramref name="request"/>. Timer/counter completion flags are one RG (FINS: one 0101) for
    /// any count; everything else is the request's own one-command word read.
    /// </summary>
    public static async Task<Snapshot> ReadSnapshotAsync(this ReadRequest request, HostLinkUnit plc, CancellationToken cancellationToken)
    {
        if (request.IsTimerCounterFlag)
        {
            bool[] flags = await plc.ReadBitsAsync(request.Address, request.Count, cancellationToken).ConfigureAwait(false);
            return new Snapshot(request, [], Array.ConvertAll(flags, f => (PlcValue?)PlcValue.FromBit(f)));
        }

        return await request.ReadAsync(plc, cancellationToken).ConfigureAwait(false);
    }
}
