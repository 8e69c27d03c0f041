using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>
/// Generic typed reads and writes. <c>T</c> picks a <see cref="PlcValueType"/> from one table and
/// <see cref="PlcValueCodec"/> converts, so every type has the same address rules, word order and validation.
/// </summary>
/// <remarks>
/// The types: <see cref="bool"/> (a bit: <c>CIO100.05</c>, <c>D10.15</c>, or a timer/counter completion flag <c>T5</c>
/// for reads), <see cref="short"/> (INT), <see cref="ushort"/> (UINT, a raw word), <see cref="int"/> (DINT),
/// <see cref="uint"/> (UDINT), <see cref="float"/> (REAL), <see cref="double"/> (LREAL, four words), <see cref="Bcd16"/>
/// (4 BCD digits in one word) and <see cref="Bcd32"/> (8 BCD digits in two words). Values of two or four words lie in
/// <see cref="WordOrder"/>; a view with another order comes from <see cref="WithWordOrder"/>. Any other
/// <c>T</c> fails with <see cref="NotSupportedException"/> before anything is sent; text has its own
/// members (<c>ReadStringAsync</c>, <c>WriteStringAsync</c>) because it has a length.
/// </remarks>
public partial class HostLinkUnit
{
    // The largest area has 32768 words: no read or write of more values can fit.
    private const int MaxValues = 32768;

    /// <summary>How this view lays 32- and 64-bit values over words (from <see cref="HostLinkClientOptions.WordOrder"/> or <see cref="WithWordOrder"/>).</summary>
    public WordOrder WordOrder => Options.WordOrder;

    /// <summary>
    /// A view of this unit that reads and writes 32- and 64-bit values in <paramref name="order"/>, for data another
    /// program laid out high word first. It shares this link; typed reads, writes, tags and watches of the view use the order.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="order"/> is not a defined <see cref="OmronHostLink.WordOrder"/>.</exception>
    public HostLinkUnit WithWordOrder(WordOrder order)
    {
        if (order is not (WordOrder.LowWordFirst or WordOrder.HighWordFirst))
        {
            throw new ArgumentOutOfRangeException(nameof(order), order, "WordOrder is LowWordFirst or HighWordFirst.");
        }

        HostLinkClientOptions options = Options.Clone();
        options.WordOrder = order;
        return new UnitView(Connection, options, UnitNumber, Models, CompoundReads);
    }

    /// <summary>Reads one value of type <typeparamref name="T"/> at <paramref name="address"/>.</summary>
    /// <typeparam name="T">bool, short, ushort, int, uint, float, double, <see cref="Bcd16"/> or <see cref="Bcd32"/>.</typeparam>
    /// <param name="address">A word address (<c>D100</c>), or for <see cref="bool"/> a bit address (<c>CIO10.03</c>) or a timer/counter (<c>T5</c>: its completion flag).</param>
    /// <param name="cancellationToken">Cancels the read.</param>
    /// <returns>The value.</returns>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <exception cref="FormatException">The address is not valid (nothing is sent), or the words read are not BCD for a BCD type.</exception>
    /// <exception cref="ArgumentException">The address does not suit the type (a bit address for a number, a word address for a bool) or the words run past the area (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the read.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    public async Task<T> ReadAsync<T>(string address, CancellationToken cancellationToken = default)
        where T : struct
    {
        PlcValueType type = PlcTypeInfo<T>.Get(nameof(ReadAsync));
        PlcValue[] values = await ReadValuesAsync(PlcAddress.Parse(address), type, 1, typeof(T).Name, cancellationToken).ConfigureAwait(false);
        return PlcTypeInfo<T>.FromValue(values[0]);
    }

    /// <summary>
    /// Reads <paramref name="count"/> consecutive values of type <typeparamref name="T"/> in one read of the words they
    /// occupy (bits: consecutive bits from the bit address, across words; timers/counters: consecutive completion flags).
    /// </summary>
    /// <typeparam name="T">bool, short, ushort, int, uint, float, double, <see cref="Bcd16"/> or <see cref="Bcd32"/>.</typeparam>
    /// <param name="address">The address of the first value.</param>
    /// <param name="count">How many values, 1–32768.</param>
    /// <param name="cancellationToken">Cancels the read.</param>
    /// <returns>The values, in address order.</returns>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <exception cref="FormatException">The address is not valid (nothing is sent), or the words read are not BCD for a BCD type.</exception>
    /// <exception cref="ArgumentException">The address does not suit the type, or the values run past the area or the command set's reach (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the read.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    public async Task<T[]> ReadAsync<T>(string address, int count, CancellationToken cancellationToken = default)
        where T : struct
    {
        PlcValueType type = PlcTypeInfo<T>.Get(nameof(ReadAsync));
        PlcValue[] values = await ReadValuesAsync(PlcAddress.Parse(address), type, count, typeof(T).Name, cancellationToken).ConfigureAwait(false);
        var result = new T[values.Length];
        for (int i = 0; i < result.Length; i++)
        {
            result[i] = PlcTypeInfo<T>.FromValue(values[i]);
        }

        return result;
    }

    /// <summary>Writes one value of type <typeparamref name="T"/> at <paramref name="address"/>; completes when the PLC answered end code 00.</summary>
    /// <typeparam name="T">bool, short, ushort, int, uint, float, double, <see cref="Bcd16"/> or <see cref="Bcd32"/>.</typeparam>
    /// <param name="address">A word address, or for <see cref="bool"/> a bit address (written as <see cref="WriteBitAsync(string, bool, CancellationToken)"/> does).</param>
    /// <param name="value">The value.</param>
    /// <param name="cancellationToken">Cancels the write.</param>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <exception cref="ArgumentException">The address does not suit the type, or the words run past the area (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the write (for example: C-mode writes in RUN mode).</exception>
    /// <exception cref="FinsEndCodeException">The PLC refused a FINS write.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time (a write is repeated only with <see cref="HostLinkClientOptions.WriteRetries"/>).</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    public Task WriteAsync<T>(string address, T value, CancellationToken cancellationToken = default)
        where T : struct
    {
        PlcValueType type = PlcTypeInfo<T>.Get(nameof(WriteAsync));
        return WriteValuesAsync(PlcAddress.Parse(address), type, new[] { PlcTypeInfo<T>.ToValue(value) }, typeof(T).Name, cancellationToken);
    }

    /// <inheritdoc cref="WriteAsync{T}(string, ReadOnlyMemory{T}, CancellationToken)"/>
    public Task WriteAsync<T>(string address, T[] values, CancellationToken cancellationToken = default)
        where T : struct
        => WriteAsync(address, new ReadOnlyMemory<T>(Guard.NotNull(values)), cancellationToken);

    /// <summary>
    /// Writes consecutive values of type <typeparamref name="T"/> from <paramref name="address"/> as one command where
    /// the protocol allows (C-mode spans frames; FINS splits beyond one frame). Bits: FINS bit writes; a C-mode view
    /// refuses them unless <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/> is set, and then makes one read
    /// and one write of the words they cover (see <see cref="WriteBitAsync(PlcAddress, bool, CancellationToken)"/>).
    /// </summary>
    /// <typeparam name="T">bool, short, ushort, int, uint, float, double, <see cref="Bcd16"/> or <see cref="Bcd32"/>.</typeparam>
    /// <param name="address">The address of the first value.</param>
    /// <param name="values">The values, at least one.</param>
    /// <param name="cancellationToken">Cancels the write.</param>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <exception cref="ArgumentException">No values, the address does not suit the type, or the values run past the area (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the write.</exception>
    /// <exception cref="FinsEndCodeException">The PLC refused a FINS write.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time (a write is repeated only with <see cref="HostLinkClientOptions.WriteRetries"/>).</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    public Task WriteAsync<T>(string address, ReadOnlyMemory<T> values, CancellationToken cancellationToken = default)
        where T : struct
    {
        PlcValueType type = PlcTypeInfo<T>.Get(nameof(WriteAsync));
        PlcAddress a = PlcAddress.Parse(address);
        var encoded = new PlcValue[values.Length];
        ReadOnlySpan<T> span = values.Span;
        for (int i = 0; i < encoded.Length; i++)
        {
            encoded[i] = PlcTypeInfo<T>.ToValue(span[i]);
        }

        return WriteValuesAsync(a, type, encoded, typeof(T).Name, cancellationToken);
    }

    private async ValueTask<PlcValue[]> ReadValuesAsync(PlcAddress address, PlcValueType type, int count, string typeName, CancellationToken cancellationToken)
    {
        Guard.InRange(count, 1, MaxValues, nameof(count));
        if (type == PlcValueType.Bit)
        {
            if (address.Area is PlcArea.Timer or PlcArea.Counter && !address.IsBit)
            {
                bool[] flags = await ReadCompletionFlagsAsync(address, count, cancellationToken).ConfigureAwait(false);
                return Array.ConvertAll(flags, PlcValue.FromBit);
            }

            EnsureBitAddress(address, typeName);
            ushort[] covering = await ReadWordsAsync(address.AsWord(), PlcValueCodec.WordCount(type, count, address.Bit), cancellationToken).ConfigureAwait(false);
            return PlcValueCodec.DecodeValues(type, covering, count, Options.WordOrder, address.Bit);
        }

        EnsureWordAddress(address, type, typeName);
        ushort[] words = await ReadWordsAsync(address, PlcValueCodec.WordCount(type, count), cancellationToken).ConfigureAwait(false);
        return PlcValueCodec.DecodeValues(type, words, count, Options.WordOrder);
    }

    private async Task WriteValuesAsync(PlcAddress address, PlcValueType type, PlcValue[] values, string typeName, CancellationToken cancellationToken)
    {
        if (values.Length == 0)
        {
            throw new ArgumentException("There is nothing to write: give at least one value.", nameof(values));
        }

        Guard.InRange(values.Length, 1, MaxValues, nameof(values));
        if (type == PlcValueType.Bit)
        {
            EnsureBitAddress(address, typeName, forWrite: true);
            if (values.Length == 1)
            {
                await WriteBitAsync(address, values[0].ToBoolean(), cancellationToken).ConfigureAwait(false);
            }
            else
            {
                await WriteBitsAsync(address, Array.ConvertAll(values, v => v.ToBoolean()), cancellationToken).ConfigureAwait(false);
            }

            return;
        }

        EnsureWordAddress(address, type, typeName);
        var words = new ushort[PlcValueCodec.WordCount(type, values.Length)];
        int at = 0;
        foreach (PlcValue value in values)
        {
            at += PlcValueCodec.Encode(value, words.AsSpan(at), Options.WordOrder);
        }

        await WriteWordsAsync(address, words, cancellationToken).ConfigureAwait(false);
    }

    private static void EnsureBitAddress(PlcAddress address, string typeName, bool forWrite = false)
    {
        if (!address.IsBit)
        {
            string flags = forWrite || address.Area is PlcArea.Timer or PlcArea.Counter ? string.Empty : " or a timer/counter completion flag such as T5";
            throw new ArgumentException($"{address} names a word; {typeName} values are bits: give a bit address such as {address}.05{flags}.", "address");
        }
    }

    private static void EnsureWordAddress(PlcAddress address, PlcValueType type, string typeName)
    {
        if (address.IsBit)
        {
            int words = type.WordsPerValue();
            throw new ArgumentException($"{address} names a bit; a {typeName} value takes {words} word{(words == 1 ? string.Empty : "s")} from a word address such as {address.AsWord()}.", "address");
        }
    }
}
