using System.Buffers;
using OmronHostLink.Link;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>
/// The jobs both command sets can do, done with C-mode: RD and the other area reads (one command however long; the
/// answer spans frames), WD and the other area writes, RG for completion flags, MS and SC. C-mode has no bit write:
/// bits are written by reading and writing back their words where <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/>
/// allows it, and refused otherwise.
/// </summary>
internal sealed class CModeUnitCommands : UnitCommandSet
{
    public static readonly CModeUnitCommands Instance = new();

    private CModeUnitCommands()
    {
    }

    public override HostLinkCommandSet Kind => HostLinkCommandSet.CMode;

#if NET
    [System.Runtime.CompilerServices.AsyncMethodBuilder(typeof(System.Runtime.CompilerServices.PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    public override async ValueTask<ushort[]> ReadWordsAsync(HostLinkUnit unit, PlcAddress address, int count, PlcModelProfile? model, CancellationToken cancellationToken)
    {
        // The hot path: no command object and no message array (a pooled buffer carries the message); the only
        // allocation of the protocol work is the result.
        (CModeArea area, int begin) = CModeAddressing.Map(address, model);
        int length = AreaReadCommand.GetMessageLength(area);
        byte[] message = ArrayPool<byte>.Shared.Rent(length);
        try
        {
            AreaReadCommand.WriteMessage(unit.UnitNumber, area, begin, count, address.Bank, message);
            string header = CModeAreaInfo.ReadHeader(area);
            var request = new HostLinkRequest(unit.UnitNumber, header, message.AsMemory(0, length), AreaReadCommand.GetExchange(area, count)) { ReadOnly = true };
            return await unit.Connection.ExecuteAsync(
                request,
                unit.RetriesFor(CommandEffect.ReadOnly),
                static (text, s) =>
                {
                    ReadOnlySpan<byte> data = CModeResponse.GetData(text, s.header, s.unit);
                    var words = new ushort[s.count];
                    CModeResponse.ReadWords(data, words);
                    return words;
                },
                (count, header, unit: unit.UnitNumber),
                cancellationToken).ConfigureAwait(false);
        }
        finally
        {
            ArrayPool<byte>.Shared.Return(message);
        }
    }

    public override async Task WriteWordsAsync(HostLinkUnit unit, PlcAddress address, ReadOnlyMemory<ushort> words, PlcModelProfile? model, CancellationToken cancellationToken)
    {
        (CModeArea area, int begin) = CModeAddressing.Map(address, model);
        var command = new AreaWriteCommand(area, begin, words.Span, address.Bank);
        await unit.CModeAsync(command, static (data, h) => HostLinkUnit.ExpectEmpty(data, h), command.Header, cancellationToken).ConfigureAwait(false);
    }

    public override async ValueTask<bool[]> ReadCompletionFlagsAsync(HostLinkUnit unit, PlcAddress address, int count, PlcModelProfile? model, CancellationToken cancellationToken)
    {
        (_, int begin) = CModeAddressing.Map(address, model);
        var command = new AreaReadCommand(CModeArea.TimerCounterStatus, begin, count);
        return await unit.CModeAsync(
            command,
            static (data, n) =>
            {
                var flags = new bool[n];
                CModeResponse.ReadFlags(data, flags);
                return flags;
            },
            count,
            cancellationToken).ConfigureAwait(false);
    }

    /// <summary>
    /// C-mode has no bit write: refused (nothing is sent) unless <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/>
    /// is set; then one read of the words the bits cover and one write of them back, so anything the PLC program writes
    /// to those words in between is lost.
    /// </summary>
    public override async Task WriteBitsAsync(HostLinkUnit unit, PlcAddress address, ReadOnlyMemory<bool> values, CancellationToken cancellationToken)
    {
        if (!unit.Options.AllowReadModifyWriteBits)
        {
            throw unit.BitWriteRefusal(address, values.Length);
        }

        PlcAddress first = address.AsWord();
        int count = WordsCovered(address, values.Length);
        first.EnsureRange(count, Kind, forWrite: unit.Models.Off);
        ushort[] words = await unit.ReadWordsAsync(first, count, cancellationToken).ConfigureAwait(false);
        for (int i = 0; i < values.Length; i++)
        {
            int n = address.Bit + i;
            words[n / 16] = PlcWords.SetBit(words[n / 16], n % 16, values.Span[i]);
        }

        await unit.WriteWordsAsync(first, words, cancellationToken).ConfigureAwait(false);
    }

    public override Task<PlcStatus> ReadStatusAsync(HostLinkUnit unit, CancellationToken cancellationToken)
        => unit.CModeAsync(CModeCommands.StatusReadCommand, static (data, _) => CModeResponse.ReadStatus(data), 0, cancellationToken).AsTask();

    public override async Task SetModeAsync(HostLinkUnit unit, PlcMode mode, CancellationToken cancellationToken)
        => await unit.CModeAsync(new StatusChangeCommand(mode), static (data, _) => HostLinkUnit.ExpectEmpty(data, "SC"), 0, cancellationToken).ConfigureAwait(false);
}
