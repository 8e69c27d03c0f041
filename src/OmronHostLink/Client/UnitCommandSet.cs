namespace OmronHostLink;

/// <summary>
/// How a unit view does the jobs both command sets can do — read and write words, read completion flags, write bits,
/// read the status, change the mode — in one command set. A view takes its object once, from its
/// <see cref="HostLinkClientOptions.CommandSet"/> (as MQTTnet picks a packet formatter per protocol version), and its
/// methods do not ask again. A planned read names its command by kind and calls the object of that kind.
/// </summary>
internal abstract class UnitCommandSet
{
    /// <summary>The object of <paramref name="commandSet"/>.</summary>
    public static UnitCommandSet For(HostLinkCommandSet commandSet)
        => commandSet == HostLinkCommandSet.Fins ? FinsUnitCommands.Instance : CModeUnitCommands.Instance;

    /// <summary>Which command set this is.</summary>
    public abstract HostLinkCommandSet Kind { get; }

    /// <summary>
    /// Refuses, before anything is sent, what <paramref name="model"/> does not have or accept with this command set.
    /// Without a model, a write is held to the CS/CJ rules (A0–A447 read-only); with one, to the model's own read-only
    /// ranges (the C-series AR words are writable).
    /// </summary>
    /// <exception cref="ArgumentException">The model lacks the range, or the command set.</exception>
    public virtual void EnsureModel(PlcModelProfile? model, PlcAddress address, int count, bool forWrite)
    {
        if (model is null)
        {
            if (forWrite)
            {
                address.AsWord().EnsureRange(count, Kind, forWrite: true);
            }

            return;
        }

        model.EnsureRange(address.AsWord(), count, forWrite);
    }

    /// <summary>Reads <paramref name="count"/> words from <paramref name="address"/> (a word address in range).</summary>
    public abstract ValueTask<ushort[]> ReadWordsAsync(HostLinkUnit unit, PlcAddress address, int count, PlcModelProfile? model, CancellationToken cancellationToken);

    /// <summary>Writes <paramref name="words"/> from <paramref name="address"/> (a word address in range).</summary>
    public abstract Task WriteWordsAsync(HostLinkUnit unit, PlcAddress address, ReadOnlyMemory<ushort> words, PlcModelProfile? model, CancellationToken cancellationToken);

    /// <summary>Reads <paramref name="count"/> timer/counter completion flags from <paramref name="address"/> (in range).</summary>
    public abstract ValueTask<bool[]> ReadCompletionFlagsAsync(HostLinkUnit unit, PlcAddress address, int count, PlcModelProfile? model, CancellationToken cancellationToken);

    /// <summary>Writes consecutive bits from the bit address <paramref name="address"/>, continuing across words.</summary>
    public abstract Task WriteBitsAsync(HostLinkUnit unit, PlcAddress address, ReadOnlyMemory<bool> values, CancellationToken cancellationToken);

    /// <summary>Reads the operating mode, the status word (where the command set has one) and any FAL/FALS message.</summary>
    public abstract Task<PlcStatus> ReadStatusAsync(HostLinkUnit unit, CancellationToken cancellationToken);

    /// <summary>Changes the operating mode.</summary>
    public abstract Task SetModeAsync(HostLinkUnit unit, PlcMode mode, CancellationToken cancellationToken);

    /// <summary>Words a run of <paramref name="bits"/> bits from <paramref name="address"/> covers.</summary>
    internal static int WordsCovered(PlcAddress address, int bits) => (address.Bit + bits + 15) / 16;
}
