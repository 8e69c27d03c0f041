namespace OmronHostLink;
public partial class HostLinkUnit
{
    private ValueTask<ushort[]> FinsReadWordsAsync(PlcAddress a, int c, CancellationToken t) => throw new NotSupportedException();
    private ValueTask FinsWriteWordsAsync(PlcAddress a, ReadOnlyMemory<ushort> w, CancellationToken t) => throw new NotSupportedException();
    private ValueTask FinsWriteBitAsync(PlcAddress a, bool v, CancellationToken t) => throw new NotSupportedException();
    private ValueTask<bool> FinsReadCompletionFlagAsync(PlcAddress a, CancellationToken t) => throw new NotSupportedException();
}
