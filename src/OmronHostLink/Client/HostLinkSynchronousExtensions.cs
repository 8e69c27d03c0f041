using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>
/// Synchronous calls for code that polls from a timer (a WinForms or VB.NET <c>Timer.Tick</c>, a .NET Framework
/// service loop): words, typed values, bits, text, tags, status, mode, errors, model and test, on any
/// <see cref="IHostLinkUnit"/> — a <see cref="HostLinkClient"/>, a unit view, or a test double.
/// </summary>
/// <remarks>
/// <para>
/// Each call runs the asynchronous method of the same name and waits for it, so both share one implementation: the
/// same validation before the wire, the same deadlines from the line speed, the same retries and resynchronisation, and
/// the same exceptions. A failure is thrown as the library's own exception (<see cref="HostLinkEndCodeException"/>,
/// <see cref="HostLinkTimeoutException"/>, …), never wrapped in <see cref="AggregateException"/>.
/// </para>
/// <para>
/// Safe on a UI thread: the library never resumes on the caller's <see cref="SynchronizationContext"/>, so waiting on
/// it cannot deadlock. The thread waits for the exchange (milliseconds at 9600 bps for a short read, up to the deadline
/// when the PLC is silent); a form that must stay responsive while a PLC is away uses the asynchronous methods or
/// <see cref="HostLinkWatcher"/>. Each waiting call holds a thread: for many PLCs polled at once from the thread pool,
/// prefer the asynchronous methods.
/// </para>
/// <para>
/// What a caller catches: <see cref="HostLinkException"/> for everything the link or the PLC reports (its
/// <see cref="HostLinkException.IsTransient"/> says whether trying again may succeed), or its kinds —
/// <see cref="HostLinkEndCodeException"/> / <see cref="FinsEndCodeException"/> (the PLC refused: wrong mode, address),
/// <see cref="HostLinkTimeoutException"/> (no answer), <see cref="HostLinkFrameException"/> (a damaged or foreign answer),
/// <see cref="HostLinkConnectionException"/> (the port or socket failed or was closed). Bad input is refused with
/// <see cref="ArgumentException"/> or <see cref="FormatException"/> before anything is sent, and a disposed client
/// throws <see cref="ObjectDisposedException"/>.
/// </para>
/// </remarks>
/// <example>
/// <code>
/// ' VB.NET, from a Timer.Tick handler
/// Dim dm As UShort() = plc.ReadWords("D100", 10)
/// plc.WriteBcd("D200", 1234)
/// Dim mode As PlcMode = plc.ReadStatus().Mode
/// </code>
/// </example>
public static class HostLinkSynchronousExtensions
{
    // ---- Words ----

    /// <summary>Reads <paramref name="count"/> consecutive words; see <see cref="HostLinkUnit.ReadWordsAsync(string, int, CancellationToken)"/>.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The first word: <c>D100</c>, <c>CIO 10</c>, <c>H5</c>, <c>E1_200</c>.</param>
    /// <param name="count">How many words, at least 1.</param>
    /// <returns>The words.</returns>
    /// <exception cref="FormatException">The address is not valid (nothing is sent).</exception>
    /// <exception cref="ArgumentException">The range does not fit the area or the command set (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the read.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged or not the answer to this command.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened or was lost.</exception>
    public static ushort[] ReadWords(this IHostLinkUnit unit, string address, int count)
        => Wait(Guard.NotNull(unit).ReadWordsAsync(address, count));

    /// <summary>Reads one word.</summary>
    /// <inheritdoc cref="ReadWords(IHostLinkUnit, string, int)" path="/exception"/>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The word.</param>
    /// <returns>The word.</returns>
    public static ushort ReadWord(this IHostLinkUnit unit, string address)
        => Wait(Guard.NotNull(unit).ReadWordsAsync(address, 1))[0];

    /// <summary>
    /// Writes consecutive words as one command; returns only when the PLC answered end code 00. See
    /// <see cref="HostLinkUnit.WriteWordsAsync(string, ReadOnlyMemory{ushort}, CancellationToken)"/>.
    /// </summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The first word.</param>
    /// <param name="words">The words, at least one.</param>
    /// <exception cref="FormatException">The address is not valid (nothing is sent).</exception>
    /// <exception cref="ArgumentException">The range does not fit the area or the command set (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the write (end code 01: C-mode writes are refused in RUN mode; use MONITOR).</exception>
    /// <exception cref="FinsEndCodeException">The PLC refused a FINS write.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time (writes are repeated only with <see cref="HostLinkClientOptions.WriteRetries"/>).</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged or not the answer to this command.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened or was lost.</exception>
    public static void WriteWords(this IHostLinkUnit unit, string address, params ushort[] words)
        => Wait(Guard.NotNull(unit).WriteWordsAsync(address, Guard.NotNull(words)));

    /// <summary>Writes one word.</summary>
    /// <inheritdoc cref="WriteWords(IHostLinkUnit, string, ushort[])" path="/exception"/>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The word.</param>
    /// <param name="value">The value.</param>
    public static void WriteWord(this IHostLinkUnit unit, string address, ushort value)
        => Wait(Guard.NotNull(unit).WriteWordsAsync(address, new[] { value }));

    // ---- Typed values ----

    /// <summary>
    /// Reads one value of type <typeparamref name="T"/> (bool, short, ushort, int, uint, float, double,
    /// <see cref="Bcd16"/>, <see cref="Bcd32"/>) in the unit's word order; see <see cref="HostLinkUnit.ReadAsync{T}(string, CancellationToken)"/>.
    /// </summary>
    /// <typeparam name="T">The value's type.</typeparam>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">A word address (a bit address for bool).</param>
    /// <returns>The value.</returns>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <inheritdoc cref="ReadWords(IHostLinkUnit, string, int)" path="/exception"/>
    public static T Read<T>(this IHostLinkUnit unit, string address)
        where T : struct
        => Wait(Guard.NotNull(unit).ReadAsync<T>(address));

    /// <summary>Reads <paramref name="count"/> consecutive values of type <typeparamref name="T"/>.</summary>
    /// <typeparam name="T">The values' type.</typeparam>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The address of the first value.</param>
    /// <param name="count">How many values.</param>
    /// <returns>The values.</returns>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <inheritdoc cref="ReadWords(IHostLinkUnit, string, int)" path="/exception"/>
    public static T[] Read<T>(this IHostLinkUnit unit, string address, int count)
        where T : struct
        => Wait(Guard.NotNull(unit).ReadAsync<T>(address, count));

    /// <summary>Writes one value of type <typeparamref name="T"/>; a bool is a bit write (see <see cref="WriteBit"/>).</summary>
    /// <typeparam name="T">The value's type.</typeparam>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">A word address (a bit address for bool).</param>
    /// <param name="value">The value.</param>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <inheritdoc cref="WriteWords(IHostLinkUnit, string, ushort[])" path="/exception"/>
    public static void Write<T>(this IHostLinkUnit unit, string address, T value)
        where T : struct
        => Wait(Guard.NotNull(unit).WriteAsync(address, value));

    /// <summary>Writes consecutive values of type <typeparamref name="T"/> as one command where the protocol allows.</summary>
    /// <typeparam name="T">The values' type.</typeparam>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The address of the first value.</param>
    /// <param name="values">The values, at least one.</param>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not one of the supported types (nothing is sent).</exception>
    /// <inheritdoc cref="WriteWords(IHostLinkUnit, string, ushort[])" path="/exception"/>
    public static void Write<T>(this IHostLinkUnit unit, string address, T[] values)
        where T : struct
        => Wait(Guard.NotNull(unit).WriteAsync(address, values));

    /// <summary>Reads a 4-digit BCD word (0-9999), as DM words holding BCD setpoints and counts are.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The word.</param>
    /// <returns>The value, 0-9999.</returns>
    /// <exception cref="FormatException">The address is not valid, or the word holds a nibble above 9: it is not BCD.</exception>
    /// <inheritdoc cref="ReadWords(IHostLinkUnit, string, int)" path="/exception"/>
    public static int ReadBcd(this IHostLinkUnit unit, string address)
        => Wait(Guard.NotNull(unit).ReadAsync<Bcd16>(address)).Value;

    /// <summary>Writes a value 0-9999 as a 4-digit BCD word.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The word.</param>
    /// <param name="value">The value, 0-9999.</param>
    /// <exception cref="ArgumentOutOfRangeException">The value is outside 0-9999 (nothing is sent).</exception>
    /// <inheritdoc cref="WriteWords(IHostLinkUnit, string, ushort[])" path="/exception"/>
    public static void WriteBcd(this IHostLinkUnit unit, string address, int value)
    {
        var bcd = new Bcd16(value);
        Wait(Guard.NotNull(unit).WriteAsync(address, bcd));
    }

    // ---- Bits and text ----

    /// <summary>
    /// Reads one bit (<c>CIO 10.03</c>, <c>H5.15</c>, <c>D100.00</c>) or a timer/counter completion flag (<c>T5</c>);
    /// see <see cref="HostLinkUnit.ReadBitAsync(string, CancellationToken)"/>.
    /// </summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The bit.</param>
    /// <returns>The bit.</returns>
    /// <exception cref="ArgumentException">The address names a word, or the command set cannot reach it (a C-mode client and the work area W): nothing is sent.</exception>
    /// <inheritdoc cref="ReadWords(IHostLinkUnit, string, int)" path="/exception"/>
    public static bool ReadBit(this IHostLinkUnit unit, string address)
        => Wait(Guard.NotNull(unit).ReadBitAsync(address));

    /// <summary>
    /// Writes one bit with FINS. A C-mode client refuses (C-mode has no bit write) and says how to switch; see
    /// <see cref="HostLinkUnit.WriteBitAsync(string, bool, CancellationToken)"/>.
    /// </summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The bit.</param>
    /// <param name="value">The value.</param>
    /// <exception cref="ArgumentException">The address names a word, or the client uses C-mode (nothing is sent).</exception>
    /// <inheritdoc cref="WriteWords(IHostLinkUnit, string, ushort[])" path="/exception"/>
    public static void WriteBit(this IHostLinkUnit unit, string address, bool value)
        => Wait(Guard.NotNull(unit).WriteBitAsync(address, value));

    /// <summary>Reads ASCII text stored two characters a word, up to <paramref name="length"/> characters or the first NUL.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The first word.</param>
    /// <param name="length">The most characters to read.</param>
    /// <returns>The text.</returns>
    /// <inheritdoc cref="ReadWords(IHostLinkUnit, string, int)" path="/exception"/>
    public static string ReadString(this IHostLinkUnit unit, string address, int length)
        => Wait(Guard.NotNull(unit).ReadStringAsync(address, length));

    /// <summary>Writes ASCII text two characters a word, high byte first (an odd length is padded with NUL).</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="address">The first word.</param>
    /// <param name="text">The text.</param>
    /// <exception cref="ArgumentException">The text holds a character outside ASCII (nothing is sent).</exception>
    /// <inheritdoc cref="WriteWords(IHostLinkUnit, string, ushort[])" path="/exception"/>
    public static void WriteString(this IHostLinkUnit unit, string address, string text)
        => Wait(Guard.NotNull(unit).WriteStringAsync(address, text));

    /// <summary>
    /// Reads tags given as text (<c>"D100:float"</c>, <c>"CIO 10.03"</c>, <c>"D20:bcd"</c>) in the fewest transactions;
    /// see <see cref="HostLinkUnit.ReadTagsAsync(IReadOnlyList{string}, CancellationToken)"/>.
    /// </summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="tags">The tags, at least one.</param>
    /// <returns>The values, in the order of <paramref name="tags"/>.</returns>
    /// <exception cref="FormatException">A tag is not valid (nothing is sent).</exception>
    /// <inheritdoc cref="ReadWords(IHostLinkUnit, string, int)" path="/exception"/>
    public static PlcTagValue[] ReadTags(this IHostLinkUnit unit, params string[] tags)
        => Wait(Guard.NotNull(unit).ReadTagsAsync(Guard.NotNull(tags)));

    // ---- Status, mode, errors, model, test ----

    /// <summary>Reads the operating mode, the status word and any FAL/FALS message.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <returns>The status.</returns>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the command.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged or not the answer to this command.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened or was lost.</exception>
    public static PlcStatus ReadStatus(this IHostLinkUnit unit)
        => Wait(Guard.NotNull(unit).ReadStatusAsync());

    /// <summary>
    /// Changes the operating mode. Leaving RUN or MONITOR stops the machine's program: the caller decides that. C-mode
    /// writes need MONITOR (or PROGRAM) mode.
    /// </summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="mode">The mode.</param>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the change.</exception>
    /// <exception cref="FinsEndCodeException">The PLC refused a FINS change.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time (the change is not repeated).</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged or not the answer to this command.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened or was lost.</exception>
    public static void SetMode(this IHostLinkUnit unit, PlcMode mode)
        => Wait(Guard.NotNull(unit).SetModeAsync(mode));

    /// <summary>Reads the error information, clearing the errors afterwards when <paramref name="clear"/> is true.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="clear">Clear the errors after reading them.</param>
    /// <returns>The error information.</returns>
    /// <inheritdoc cref="ReadStatus(IHostLinkUnit)" path="/exception"/>
    public static PlcErrorInfo ReadErrors(this IHostLinkUnit unit, bool clear = false)
        => Wait(Guard.NotNull(unit).ReadErrorsAsync(clear));

    /// <summary>Reads the PLC model code.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <returns>The model.</returns>
    /// <inheritdoc cref="ReadStatus(IHostLinkUnit)" path="/exception"/>
    public static PlcModel ReadModel(this IHostLinkUnit unit)
        => Wait(Guard.NotNull(unit).ReadModelAsync());

    /// <summary>Sends TEST with <paramref name="text"/> and checks that the PLC echoes it unchanged.</summary>
    /// <param name="unit">The client or unit view.</param>
    /// <param name="text">Up to 122 characters that can travel in a frame.</param>
    /// <returns>The round-trip time.</returns>
    /// <exception cref="ArgumentException">The text is too long or cannot travel in a frame (nothing is sent).</exception>
    /// <inheritdoc cref="ReadStatus(IHostLinkUnit)" path="/exception"/>
    public static TimeSpan Test(this IHostLinkUnit unit, string text = "OMRONHOSTLINK")
        => Wait(Guard.NotNull(unit).TestAsync(text));

    // GetResult, not Result or Wait(): it throws the library's exception itself, not an AggregateException around it.
    private static T Wait<T>(Task<T> task) => task.GetAwaiter().GetResult();

    private static void Wait(Task task) => task.GetAwaiter().GetResult();
}
