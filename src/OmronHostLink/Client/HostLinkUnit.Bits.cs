using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>Runs of consecutive bits read or written as one command.</summary>
public partial class HostLinkUnit
{
    /// <summary>
    /// Reads <paramref name="count"/> consecutive bits from <paramref name="address"/> in one command: bits of a word
    /// area (<c>CIO100.14</c>, continuing across word boundaries) from one read of the words they cover, or timer/counter
    /// completion flags (<c>T0</c>, <c>C10</c>: that flag and the next ones) from one C-mode RG or FINS 0101 (split only
    /// beyond one answer frame's bits).
    /// </summary>
    /// <exception cref="ArgumentException">The address names a word of a word area, or the range does not fit the area or the protocol (nothing is sent).</exception>
    public async Task<bool[]> ReadBitsAsync(PlcAddress address, int count, CancellationToken cancellationToken = default)
    {
        Guard.InRange(count, 1, 10000, nameof(count));
        if (address.Area is PlcArea.Timer or PlcArea.Counter)
        {
            return await ReadCompletionFlagsAsync(address, count, cancellationToken).ConfigureAwait(false);
        }

        EnsureBitAddress(address);
        ushort[] words = await ReadWordsAsync(address.AsWord(), UnitCommandSet.WordsCovered(address, count), cancellationToken).ConfigureAwait(false);
        var bits = new bool[count];
        for (int i = 0; i < count; i++)
        {
            int n = address.Bit + i;
            bits[i] = PlcWords.GetBit(words[n / 16], n % 16);
        }

        return bits;
    }

    /// <summary>
    /// Writes consecutive bits from <paramref name="address"/> (continuing across word boundaries) as one command: FINS
    /// 0102 on the bits (split only beyond one frame's <see cref="MemoryAreaWriteCommand.MaxDataBytes"/> bits). C-mode has
    /// no bit write: a C-mode view refuses, as <see cref="WriteBitAsync(PlcAddress, bool, CancellationToken)"/> does, unless
    /// <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/> is set: then one read of the words the bits cover and
    /// one write of them back, so anything the PLC program writes to those words in between is lost.
    /// </summary>
    /// <exception cref="ArgumentException">The address names a word, the range does not fit the area or the protocol, or this view uses C-mode (nothing is sent).</exception>
    public async Task WriteBitsAsync(PlcAddress address, ReadOnlyMemory<bool> values, CancellationToken cancellationToken = default)
    {
        EnsureBitAddress(address);
        Guard.InRange(values.Length, 1, 10000, nameof(values));
        await Commands.WriteBitsAsync(this, address, values, cancellationToken).ConfigureAwait(false);
    }

    private static void EnsureBitAddress(PlcAddress address)
    {
        if (!address.IsBit)
        {
            throw new ArgumentException($"{address} names a word; a bit address has a bit number, as in {address}.05.", nameof(address));
        }
    }
}
