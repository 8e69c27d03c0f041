namespace OmronHostLink;

/// <summary>Typed reads and writes by name (shortcuts for the generic members), text and bits.</summary>
public partial class HostLinkUnit
{
    /// <summary>Reads a signed 16-bit value (INT); the same as <c>ReadAsync&lt;short&gt;</c>.</summary>
    public Task<short> ReadInt16Async(string address, CancellationToken cancellationToken = default)
        => ReadAsync<short>(address, cancellationToken);

    /// <summary>Reads an unsigned 16-bit value (UINT); the same as <c>ReadAsync&lt;ushort&gt;</c>.</summary>
    public Task<ushort> ReadUInt16Async(string address, CancellationToken cancellationToken = default)
        => ReadAsync<ushort>(address, cancellationToken);

    /// <summary>Reads a signed 32-bit value (DINT) from two words in <see cref="WordOrder"/>; the same as <c>ReadAsync&lt;int&gt;</c>.</summary>
    public Task<int> ReadInt32Async(string address, CancellationToken cancellationToken = default)
        => ReadAsync<int>(address, cancellationToken);

    /// <summary>Reads an unsigned 32-bit value (UDINT) from two words; the same as <c>ReadAsync&lt;uint&gt;</c>.</summary>
    public Task<uint> ReadUInt32Async(string address, CancellationToken cancellationToken = default)
        => ReadAsync<uint>(address, cancellationToken);

    /// <summary>Reads an IEEE 754 single (REAL) from two words; the same as <c>ReadAsync&lt;float&gt;</c>.</summary>
    public Task<float> ReadSingleAsync(string address, CancellationToken cancellationToken = default)
        => ReadAsync<float>(address, cancellationToken);

    /// <summary>Reads a 4-digit BCD word (0-9999); the same as <c>ReadAsync&lt;Bcd16&gt;</c>.</summary>
    /// <exception cref="FormatException">The word holds a nibble above 9: it is not BCD.</exception>
    public async Task<int> ReadBcdAsync(string address, CancellationToken cancellationToken = default)
        => (await ReadAsync<Bcd16>(address, cancellationToken).ConfigureAwait(false)).Value;

    /// <summary>Reads ASCII text stored two characters a word, high byte first, up to <paramref name="length"/> characters or the first NUL.</summary>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the command (its end code, header and unit are in the exception).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public async Task<string> ReadStringAsync(string address, int length, CancellationToken cancellationToken = default)
    {
        Guard.InRange(length, 1, 20000);
        return PlcWords.ReadString(await ReadWordsAsync(address, PlcWords.WordsForString(length), cancellationToken).ConfigureAwait(false));
    }

    /// <summary>Writes a signed 16-bit value (INT).</summary>
    public Task WriteInt16Async(string address, short value, CancellationToken cancellationToken = default)
        => WriteAsync(address, value, cancellationToken);

    /// <summary>Writes an unsigned 16-bit value (UINT).</summary>
    public Task WriteUInt16Async(string address, ushort value, CancellationToken cancellationToken = default)
        => WriteAsync(address, value, cancellationToken);

    /// <summary>Writes a signed 32-bit value (DINT) to two words in <see cref="WordOrder"/>.</summary>
    public Task WriteInt32Async(string address, int value, CancellationToken cancellationToken = default)
        => WriteAsync(address, value, cancellationToken);

    /// <summary>Writes an unsigned 32-bit value (UDINT) to two words.</summary>
    public Task WriteUInt32Async(string address, uint value, CancellationToken cancellationToken = default)
        => WriteAsync(address, value, cancellationToken);

    /// <summary>Writes an IEEE 754 single (REAL) to two words.</summary>
    public Task WriteSingleAsync(string address, float value, CancellationToken cancellationToken = default)
        => WriteAsync(address, value, cancellationToken);

    /// <summary>Writes a value 0-9999 as a 4-digit BCD word; the same as <c>WriteAsync(address, new Bcd16(value))</c>.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is outside 0-9999 (nothing is sent).</exception>
    public Task WriteBcdAsync(string address, int value, CancellationToken cancellationToken = default)
        => WriteAsync(address, new Bcd16(value), cancellationToken);

    /// <summary>Writes ASCII text two characters a word, high byte first (an odd length is padded with NUL).</summary>
    /// <exception cref="ArgumentException">The text holds a character outside ASCII (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the write (01: C-mode writes are refused in RUN mode).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time (a write is repeated only with <see cref="HostLinkClientOptions.WriteRetries"/>).</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public Task WriteStringAsync(string address, string text, CancellationToken cancellationToken = default)
        => WriteWordsAsync(address, PlcWords.FromString(text), cancellationToken);

    /// <summary>
    /// Reads one bit: <c>CIO100.05</c>, <c>W30.06</c>, <c>D100.15</c>, or a timer/counter completion flag (<c>T5</c>, <c>C7</c>),
    /// with this view's command set (the word that holds it, or the flag). C-mode cannot reach the work area (W): a
    /// C-mode view refuses <c>W30.06</c> before anything is sent, naming how to use FINS.
    /// </summary>
    /// <exception cref="ArgumentException">The address names a word, not a bit, or the command set cannot reach it (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the read.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged or not the answer to this command.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened or was lost.</exception>
    public Task<bool> ReadBitAsync(string address, CancellationToken cancellationToken = default)
        => ReadBitAsync(PlcAddress.Parse(address), cancellationToken);

    /// <inheritdoc cref="ReadBitAsync(string, CancellationToken)"/>
    public async Task<bool> ReadBitAsync(PlcAddress address, CancellationToken cancellationToken = default)
    {
        if (address.Area is PlcArea.Timer or PlcArea.Counter)
        {
            return (await ReadCompletionFlagsAsync(address, 1, cancellationToken).ConfigureAwait(false))[0];
        }

        if (!address.IsBit)
        {
            throw new ArgumentException($"{address} names a word; a bit address has a bit number, as in {address}.05.", nameof(address));
        }

        ushort word = (await ReadWordsAsync(address.AsWord(), 1, cancellationToken).ConfigureAwait(false))[0];
        return PlcWords.GetBit(word, address.Bit);
    }

    /// <summary>
    /// Writes one bit with FINS MEMORY AREA WRITE (0102) on the bit. C-mode has no bit write: a C-mode view refuses
    /// (nothing is sent), naming the ways to write it — FINS (<see cref="HostLinkClientOptions.CommandSet"/> =
    /// <see cref="HostLinkCommandSet.Fins"/>, or <c>plc.Unit(0, HostLinkCommandSet.Fins)</c>) or, with
    /// <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/>, reading the word, changing the bit and writing the
    /// word back (anything the PLC program writes to that word in between is lost).
    /// </summary>
    /// <exception cref="ArgumentException">The address names a word, not a bit; or this view uses C-mode (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the write (C-mode read-modify-write in RUN mode: end code 01).</exception>
    /// <exception cref="FinsEndCodeException">The PLC refused the FINS write (for example in RUN mode on some models).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged or not the answer to this command.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened or was lost.</exception>
    public Task WriteBitAsync(string address, bool value, CancellationToken cancellationToken = default)
        => WriteBitAsync(PlcAddress.Parse(address), value, cancellationToken);

    /// <inheritdoc cref="WriteBitAsync(string, bool, CancellationToken)"/>
    public async Task WriteBitAsync(PlcAddress address, bool value, CancellationToken cancellationToken = default)
    {
        if (!address.IsBit)
        {
            throw new ArgumentException($"{address} names a word; a bit address has a bit number, as in {address}.05.", nameof(address));
        }

        await Commands.WriteBitsAsync(this, address, new[] { value }, cancellationToken).ConfigureAwait(false);
    }
}
