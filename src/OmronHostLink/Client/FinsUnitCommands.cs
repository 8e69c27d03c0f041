using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>
/// The jobs both command sets can do, done with FINS over Host Link: 0101 and 0102 (split beyond what one FA frame
/// holds, so a long read is not one snapshot), 0102 on bits, 0601 for the status, 0401/0402 for the mode.
/// </summary>
internal sealed class FinsUnitCommands : UnitCommandSet
{
    public static readonly FinsUnitCommands Instance = new();

    private FinsUnitCommands()
    {
    }

    public override HostLinkCommandSet Kind => HostLinkCommandSet.Fins;

    /// <summary>A model known to have no FINS over Host Link is refused as well.</summary>
    public override void EnsureModel(PlcModelProfile? model, PlcAddress address, int count, bool forWrite)
    {
        model?.EnsureFins();
        base.EnsureModel(model, address, count, forWrite);
    }

    public override async ValueTask<ushort[]> ReadWordsAsync(HostLinkUnit unit, PlcAddress address, int count, PlcModelProfile? model, CancellationToken cancellationToken)
    {
        // Beyond one command's limit the read is split into the fewest commands; the words are then not one snapshot.
        var words = new ushort[count];
        for (int done = 0; done < count;)
        {
            int n = Math.Min(MemoryAreaReadCommand.MaxWords, count - done);
            var command = new MemoryAreaReadCommand(FinsAddressing.Word(address.Offset(done)), n);
            await unit.FinsAsync(
                command,
                static (data, s) =>
                {
                    FinsWords.Read(data, s.words.AsSpan(s.done, s.n));
                    return true;
                },
                (words, done, n),
                cancellationToken).ConfigureAwait(false);
            done += n;
        }

        return words;
    }

    public override async Task WriteWordsAsync(HostLinkUnit unit, PlcAddress address, ReadOnlyMemory<ushort> words, PlcModelProfile? model, CancellationToken cancellationToken)
    {
        for (int done = 0; done < words.Length;)
        {
            int n = Math.Min(MemoryAreaWriteCommand.MaxWords, words.Length - done);
            var command = MemoryAreaWriteCommand.Words(FinsAddressing.Word(address.Offset(done)), words.Span.Slice(done, n));
            await unit.FinsNoDataAsync(command, cancellationToken).ConfigureAwait(false);
            done += n;
        }
    }

    public override async ValueTask<bool[]> ReadCompletionFlagsAsync(HostLinkUnit unit, PlcAddress address, int count, PlcModelProfile? model, CancellationToken cancellationToken)
    {
        // Beyond one answer frame's bits the read is split into the fewest commands, as word reads are.
        var flags = new bool[count];
        for (int done = 0; done < count;)
        {
            int n = Math.Min(MemoryAreaReadCommand.MaxBits, count - done);
            bool[] part = await unit.FinsAsync(
                new MemoryAreaReadCommand(FinsAddressing.Item(address.Offset(done)), n),
                static (data, c) => FinsBits.Read(data, c),
                n,
                cancellationToken).ConfigureAwait(false);
            part.CopyTo(flags, done);
            done += n;
        }

        return flags;
    }

    /// <summary>0102 on the bits, split only beyond one frame's <see cref="MemoryAreaWriteCommand.MaxDataBytes"/> bits.</summary>
    public override async Task WriteBitsAsync(HostLinkUnit unit, PlcAddress address, ReadOnlyMemory<bool> values, CancellationToken cancellationToken)
    {
        PlcAddress first = address.AsWord();
        int words = WordsCovered(address, values.Length);
        first.EnsureRange(words, Kind, forWrite: true);
        EnsureModel(await unit.GetModelProfileAsync(cancellationToken).ConfigureAwait(false), first, words, forWrite: true);
        for (int done = 0; done < values.Length;)
        {
            int n = Math.Min(MemoryAreaWriteCommand.MaxDataBytes, values.Length - done);
            int bit = address.Bit + done;
            PlcAddress from = first.Offset(bit / 16).WithBit(bit % 16);
            var command = MemoryAreaWriteCommand.Bits(FinsAddressing.Bit(from), values.Span.Slice(done, n));
            await unit.FinsNoDataAsync(command, cancellationToken).ConfigureAwait(false);
            done += n;
        }
    }

    /// <summary>0601 CPU UNIT STATUS READ: mode and message; it has no MS status word (its UM protection and program area bits are not reported).</summary>
    public override async Task<PlcStatus> ReadStatusAsync(HostLinkUnit unit, CancellationToken cancellationToken)
    {
        FinsCpuStatus status = await unit.ReadCpuStatusAsync(cancellationToken).ConfigureAwait(false);
        PlcMode mode = status.Mode switch
        {
            FinsCpuMode.Run => PlcMode.Run,
            FinsCpuMode.Monitor => PlcMode.Monitor,
            _ => PlcMode.Program,
        };
        string message = status.ErrorMessage.Trim();
        return new PlcStatus(mode, statusWord: null, message.Length == 0 ? null : message);
    }

    /// <summary>0402 STOP for PROGRAM mode, 0401 RUN for MONITOR and RUN.</summary>
    public override Task SetModeAsync(HostLinkUnit unit, PlcMode mode, CancellationToken cancellationToken)
        => mode == PlcMode.Program ? unit.StopAsync(cancellationToken) : unit.RunAsync(mode, cancellationToken);
}
