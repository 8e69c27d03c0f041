namespace OmronHostLink;

/// <summary>Typed reads and writes: integers, REAL, BCD, text and bits, built on the word reads and writes.</summary>
public partial class HostLinkUnit
{
    /// <summary>Reads a signed 16-bit value.</summary>
    public async ValueTask<short> ReadInt16Async(string address, CancellationToken cancellationToken = default)
        => unchecked((short)await ReadWordAsync(address, cancellationToken).ConfigureAwait(false));

    /// <summary>Reads an unsigned 16-bit value.</summary>
    public ValueTask<ushort> ReadUInt16Async(string address, CancellationToken cancellationToken = default)
        => ReadWordAsync(address, cancellationToken);

    /// <summary>Reads a signed 32-bit value from two words (word order from the options; Omron: low word first).</summary>
    public async ValueTask<int> ReadInt32Async(string address, CancellationToken cancellationToken = default)
        => PlcWords.ReadInt32(await ReadWordsAsync(address, 2, cancellationToken).ConfigureAwait(false), Options.WordOrder);

    /// <summary>Reads an unsigned 32-bit value from two words.</summary>
    public async ValueTask<uint> ReadUInt32Async(string address, CancellationToken cancellationToken = default)
        => PlcWords.ReadUInt32(await ReadWordsAsync(address, 2, cancellationToken).ConfigureAwait(false), Options.WordOrder);

    /// <summary>Reads an IEEE 754 single (REAL) from two words.</summary>
    public async ValueTask<float> ReadSingleAsync(string address, CancellationToken cancellationToken = default)
        => PlcWords.ReadSingle(await ReadWordsAsync(address, 2, cancellationToken).ConfigureAwait(false), Options.WordOrder);

    /// <summary>Reads a 4-digit BCD word (0-9999).</summary>
    /// <exception cref="FormatException">The word holds a nibble above 9: it is not BCD.</exception>
    public async ValueTask<int> ReadBcdAsync(string address, CancellationToken cancellationToken = default)
        => PlcWords.FromBcd(await ReadWordAsync(address, cancellationToken).ConfigureAwait(false));

    /// <summary>Reads ASCII text stored two characters a word, high byte first, up to <paramref name="length"/> characters or the first NUL.</summary>
    public async ValueTask<string> ReadStringAsync(string address, int length, CancellationToken cancellationToken = default)
    {
        Guard.InRange(length, 1, 20000);
        return PlcWords.ReadString(await ReadWordsAsync(address, PlcWords.WordsForString(length), cancellationToken).ConfigureAwait(false));
    }

    /// <summary>Writes a signed 16-bit value.</summary>
    public ValueTask WriteInt16Async(string address, short value, CancellationToken cancellationToken = default)
        => WriteWordAsync(address, unchecked((ushort)value), cancellationToken);

    /// <summary>Writes an unsigned 16-bit value.</summary>
    public ValueTask WriteUInt16Async(string address, ushort value, CancellationToken cancellationToken = default)
        => WriteWordAsync(address, value, cancellationToken);

    /// <summary>Writes a signed 32-bit value to two words.</summary>
    public ValueTask WriteInt32Async(string address, int value, CancellationToken cancellationToken = default)
    {
        var words = new ushort[2];
        PlcWords.WriteInt32(value, words, Options.WordOrder);
        return WriteWordsAsync(address, words, cancellationToken);
    }

    /// <summary>Writes an unsigned 32-bit value to two words.</summary>
    public ValueTask WriteUInt32Async(string address, uint value, CancellationToken cancellationToken = default)
    {
        var words = new ushort[2];
        PlcWords.WriteUInt32(value, words, Options.WordOrder);
        return WriteWordsAsync(address, words, cancellationToken);
    }

    /// <summary>Writes an IEEE 754 single (REAL) to two words.</summary>
    public ValueTask WriteSingleAsync(string address, float value, CancellationToken cancellationToken = default)
    {
        var words = new ushort[2];
        PlcWords.WriteSingle(value, words, Options.WordOrder);
        return WriteWordsAsync(address, words, cancellationToken);
    }

    /// <summary>Writes a value 0-9999 as a 4-digit BCD word.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is outside 0-9999 (nothing is sent).</exception>
    public ValueTask WriteBcdAsync(string address, int value, CancellationToken cancellationToken = default)
        => WriteWordAsync(address, PlcWords.ToBcd(value), cancellationToken);

    /// <summary>Writes ASCII text two characters a word, high byte first (an odd length is padded with NUL).</summary>
    /// <exception cref="ArgumentException">The text holds a character outside ASCII (nothing is sent).</exception>
    public ValueTask WriteStringAsync(string address, string text, CancellationToken cancellationToken = default)
        => WriteWordsAsync(address, PlcWords.FromString(text), cancellationToken);

    /// <summary>
    /// Reads one bit: <c>CIO100.05</c>, <c>W30.06</c>, <c>D100.15</c>, or a timer/counter completion flag (<c>T5</c>, <c>C7</c>).
    /// </summary>
    /// <exception cref="ArgumentException">The address names a word, not a bit.</exception>
    public ValueTask<bool> ReadBitAsync(string address, CancellationToken cancellationToken = default)
        => ReadBitAsync(PlcAddress.Parse(address), cancellationToken);

    /// <inheritdoc cref="ReadBitAsync(string, CancellationToken)"/>
    public async ValueTask<bool> ReadBitAsync(PlcAddress address, CancellationToken cancellationToken = default)
    {
        if (address.Area is PlcArea.Timer or PlcArea.Counter)
        {
            return await ReadCompletionFlagAsync(address, cancellationToken).ConfigureAwait(false);
        }

        if (!address.IsBit)
        {
            throw new ArgumentException($"{address} names a word; a bit address has a bit number, as in {address}.05.", nameof(address));
        }

        ushort word = (await ReadWordsAsync(address.AsWord(), 1, cancellationToken).ConfigureAwait(false))[0];
        return PlcWords.GetBit(word, address.Bit);
    }

    /// <summary>
    /// Writes one bit with FINS MEMORY AREA WRITE on the bit (C-mode has no bit write for data areas). With
    /// <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/> and C-mode, the word is read, changed and written
    /// back instead: anything the PLC program writes to that word in between is lost.
    /// </summary>
    /// <exception cref="ArgumentException">The address names a word, not a bit.</exception>
    public ValueTask WriteBitAsync(string address, bool value, CancellationToken cancellationToken = default)
        => WriteBitAsync(PlcAddress.Parse(address), value, cancellationToken);

    /// <inheritdoc cref="WriteBitAsync(string, bool, CancellationToken)"/>
    public async ValueTask WriteBitAsync(PlcAddress address, bool value, CancellationToken cancellationToken = default)
    {
        if (!address.IsBit)
        {
            throw new ArgumentException($"{address} names a word; a bit address has a bit number, as in {address}.05.", nameof(address));
        }

        if (Options.AllowReadModifyWriteBits && Options.CommandSet == HostLinkCommandSet.CMode)
        {
            PlcAddress word = address.AsWord();
            word.EnsureRange(1, HostLinkCommandSet.CMode, forWrite: true);
            ushort current = (await ReadWordsAsync(word, 1, cancellationToken).ConfigureAwait(false))[0];
            await WriteWordsAsync(word, new[] { PlcWords.SetBit(current, address.Bit, value) }, cancellationToken).ConfigureAwait(false);
            return;
        }

        await FinsWriteBitAsync(address, value, cancellationToken).ConfigureAwait(false);
    }
}
