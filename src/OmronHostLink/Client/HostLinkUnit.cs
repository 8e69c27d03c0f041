using System.Text;
using OmronHostLink.Link;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// One PLC on a Host Link line, addressed by its unit number. Every unit view of a client shares the client's single
/// link: their exchanges queue and never interleave on the wire. Every method validates its arguments before
/// anything is sent, and every value returned comes from a complete, validated answer.
/// </summary>
public partial class HostLinkUnit
{
    /// <summary>The highest unit number Host Link addresses (the lowest is 0).</summary>
    public const int MaxUnitNumber = HostLinkRules.MaxUnitNumber;

    internal readonly HostLinkConnection Connection;
    internal readonly HostLinkClientOptions Options;
    internal readonly UnitModels Models;

    internal readonly CompoundReadRegistry CompoundReads;

    /// <summary>This view's command set, taken once from <see cref="HostLinkClientOptions.CommandSet"/>.</summary>
    private protected readonly UnitCommandSet Commands;

    private protected HostLinkUnit(HostLinkConnection connection, HostLinkClientOptions options, int unitNumber, UnitModels models)
        : this(connection, options, unitNumber, models, new CompoundReadRegistry())
    {
    }

    private protected HostLinkUnit(HostLinkConnection connection, HostLinkClientOptions options, int unitNumber, UnitModels models, CompoundReadRegistry compoundReads)
    {
        Guard.Unit(unitNumber);
        Connection = connection;
        Options = options;
        UnitNumber = unitNumber;
        Models = models;
        CompoundReads = compoundReads;
        Commands = UnitCommandSet.For(options.CommandSet);
    }

    /// <summary>The unit number (0-31) this view addresses.</summary>
    public int UnitNumber { get; }

    /// <summary>The character timing frame deadlines are derived from.</summary>
    public LineTiming LineTiming => Connection.Timing;

    /// <summary>Which command set (C-mode or FINS) this view uses for reads, writes, status and mode where both can do the job.</summary>
    public HostLinkCommandSet CommandSet => Commands.Kind;

    /// <summary>A view of another unit on the same line (multidrop), sharing this link.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The unit number is not 0-31.</exception>
    public HostLinkUnit Unit(int unitNumber) => new UnitView(Connection, Options, unitNumber, Models, CompoundReads);

    /// <summary>A view of a unit on the same line that uses <paramref name="commandSet"/> where both command sets can do a job.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The unit number is not 0-31.</exception>
    public HostLinkUnit Unit(int unitNumber, HostLinkCommandSet commandSet)
    {
        HostLinkClientOptions options = Options.Clone();
        options.CommandSet = commandSet;
        return new UnitView(Connection, options, unitNumber, Models, CompoundReads);
    }

    // ---- Words ----

    /// <summary>
    /// Reads <paramref name="count"/> consecutive words. With C-mode the read is one command, however long (the answer
    /// spans frames), so the words are one consistent snapshot. FINS reads longer than
    /// 269 words (what one FA answer frame holds) are split into the fewest commands, and are then not one snapshot.
    /// </summary>
    /// <exception cref="FormatException">The address is not valid.</exception>
    /// <exception cref="ArgumentException">The range does not fit the area or the protocol (nothing is sent).</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the command (its end code, header and unit are in the exception).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public Task<ushort[]> ReadWordsAsync(string address, int count, CancellationToken cancellationToken = default)
        => ReadWordsAsync(PlcAddress.Parse(address), count, cancellationToken);

    /// <inheritdoc cref="ReadWordsAsync(string, int, CancellationToken)"/>
    public Task<ushort[]> ReadWordsAsync(PlcAddress address, int count, CancellationToken cancellationToken = default)
    {
        address = address.AsWord();
        address.EnsureRange(count, Commands.Kind, forWrite: false);
        if (!Models.TryGet(UnitNumber, out PlcModelProfile? model))
        {
            return ReadWordsOfDetectedModelAsync(address, count, cancellationToken);
        }

        Commands.EnsureModel(model, address, count, forWrite: false);
        return Commands.ReadWordsAsync(this, address, count, model, cancellationToken).AsTask();
    }

    /// <summary>Reads one word.</summary>
    public async Task<ushort> ReadWordAsync(string address, CancellationToken cancellationToken = default)
        => (await ReadWordsAsync(address, 1, cancellationToken).ConfigureAwait(false))[0];

    /// <summary>
    /// Writes consecutive words as one command (C-mode spans frames as needed; FINS splits writes longer than
    /// 267 words, what one FA command frame holds). Completes only when the PLC answered end code 00.
    /// </summary>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the write (for example 01: C-mode writes are refused in RUN mode).</exception>
    /// <exception cref="FinsEndCodeException">The PLC refused a FINS write.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time (a write is repeated only with <see cref="HostLinkClientOptions.WriteRetries"/>).</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public Task WriteWordsAsync(string address, ReadOnlyMemory<ushort> words, CancellationToken cancellationToken = default)
        => WriteWordsAsync(PlcAddress.Parse(address), words, cancellationToken);

    /// <inheritdoc cref="WriteWordsAsync(string, ReadOnlyMemory{ushort}, CancellationToken)"/>
    public Task WriteWordsAsync(PlcAddress address, ReadOnlyMemory<ushort> words, CancellationToken cancellationToken = default)
    {
        address = address.AsWord();
        address.EnsureRange(words.Length, Commands.Kind, forWrite: Models.Off);
        if (!Models.TryGet(UnitNumber, out PlcModelProfile? model))
        {
            return WriteWordsOfDetectedModelAsync(address, words, cancellationToken);
        }

        Commands.EnsureModel(model, address, words.Length, forWrite: true);
        return Commands.WriteWordsAsync(this, address, words, model, cancellationToken);
    }

    /// <summary>Writes one word.</summary>
    public Task WriteWordAsync(string address, ushort value, CancellationToken cancellationToken = default)
        => WriteWordsAsync(address, new[] { value }, cancellationToken);

    // ---- Status, mode, errors, model, test ----

    /// <summary>Reads the operating mode, the status word and any FAL/FALS message (C-mode MS; FINS 0601 when the protocol is FINS).</summary>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the command (its end code, header and unit are in the exception).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public Task<PlcStatus> ReadStatusAsync(CancellationToken cancellationToken = default)
        => Commands.ReadStatusAsync(this, cancellationToken);

    /// <summary>
    /// Changes the operating mode (C-mode SC; FINS 0401/0402 when the protocol is FINS). Leaving RUN or MONITOR stops
    /// the machine's program: callers decide that, not the library.
    /// </summary>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the change.</exception>
    /// <exception cref="FinsEndCodeException">The PLC refused a FINS change.</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time (a write is repeated only with <see cref="HostLinkClientOptions.WriteRetries"/>).</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public Task SetModeAsync(PlcMode mode, CancellationToken cancellationToken = default)
        => Commands.SetModeAsync(this, mode, cancellationToken);

    /// <summary>Reads the error information (MF), clearing the errors afterwards when <paramref name="clear"/> is true.</summary>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the command (its end code, header and unit are in the exception).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public Task<PlcErrorInfo> ReadErrorsAsync(bool clear = false, CancellationToken cancellationToken = default)
        => CModeAsync(new ErrorReadCommand(clear), static (data, _) => CModeResponse.ReadErrors(data), 0, cancellationToken).AsTask();

    /// <summary>Reads the PLC model code (MM).</summary>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the command (its end code, header and unit are in the exception).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public Task<PlcModel> ReadModelAsync(CancellationToken cancellationToken = default)
        => CModeAsync(CModeCommands.ModelReadCommand, static (data, _) => CModeResponse.ReadModel(data), 0, cancellationToken).AsTask();

    /// <summary>
    /// Sends TS (TEST) with <paramref name="text"/> and checks that the PLC echoes it unchanged. Returns the round-trip time.
    /// </summary>
    /// <exception cref="ArgumentException">The text is over 122 characters or holds characters that cannot travel in a frame.</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC refused the command (its end code, header and unit are in the exception).</exception>
    /// <exception cref="HostLinkTimeoutException">No answer in time, after the read retries.</exception>
    /// <exception cref="HostLinkFrameException">The answer was damaged, from another unit, or not the answer to this command: never returned as data.</exception>
    /// <exception cref="HostLinkConnectionException">The port or socket could not be opened, or was lost or closed during the exchange.</exception>
    /// <exception cref="ObjectDisposedException">The client was disposed.</exception>
    public async Task<TimeSpan> TestAsync(string text = "OMRONHOSTLINK", CancellationToken cancellationToken = default)
    {
        var command = new TestCommand(text);
        byte[] sent = Encoding.ASCII.GetBytes(text);
        var clock = System.Diagnostics.Stopwatch.StartNew();
        await Connection.ExecuteAsync(
            Request(command),
            RetriesFor(command.Effect),
            static (echo, state) =>
            {
                CModeResponse.CheckTestEcho(echo, state.sent, state.unit);
                return true;
            },
            (sent, unit: UnitNumber),
            cancellationToken).ConfigureAwait(false);
        return clock.Elapsed;
    }

    /// <summary>Sends XZ (ABORT) to this unit: it drops the exchange it is in. The PLC sends no answer.</summary>
    public async Task AbortAsync(CancellationToken cancellationToken = default)
        => await Connection.ExecuteAsync(Request(CModeCommands.AbortCommand), RetriesFor(CModeCommands.AbortCommand.Effect), static (_, _) => true, 0, cancellationToken).ConfigureAwait(false);

    /// <summary>Sends <c>@**</c> (INITIALIZE): every unit on the line resets its Host Link transmission control. No answer.</summary>
    public Task InitializeAsync(CancellationToken cancellationToken = default)
        => Connection.InitializeAsync(cancellationToken).AsTask();

    // ---- C-mode plumbing ----

    internal HostLinkRequest Request(CModeCommand command)
    {
        EnsureModelAccepts(command);
        return new(UnitNumber, command.Header, command.ToMessage(UnitNumber), command.Exchange);
    }

    /// <summary>How often a command is repeated after a timeout or damage: by what repeating it would do.</summary>
    internal int RetriesFor(CommandEffect effect) => effect switch
    {
        CommandEffect.ReadOnly => Options.ReadRetries,
        CommandEffect.Idempotent => Options.WriteRetries,
        _ => 0,
    };

    internal ValueTask<TResult> CModeAsync<TState, TResult>(CModeCommand command, ResponseDecoder<TState, TResult> decodeData, TState state, CancellationToken cancellationToken)
        => Connection.ExecuteAsync(
            Request(command),
            RetriesFor(command.Effect),
            static (text, s) => s.decodeData(CModeResponse.GetData(text, s.header, s.unit), s.state),
            (decodeData, state, header: command.Header, unit: UnitNumber),
            cancellationToken);

    private async ValueTask<bool[]> ReadCompletionFlagsAsync(PlcAddress address, int count, CancellationToken cancellationToken)
    {
        address.EnsureRange(count, Commands.Kind, forWrite: false);
        PlcModelProfile? model = await GetModelProfileAsync(cancellationToken).ConfigureAwait(false);
        Commands.EnsureModel(model, address, count, forWrite: false);
        return await Commands.ReadCompletionFlagsAsync(this, address, count, model, cancellationToken).ConfigureAwait(false);
    }

    internal static bool ExpectEmpty(ReadOnlySpan<byte> data, string header)
    {
        if (!data.IsEmpty)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"The answer to {header} should carry no data but carried {data.Length} characters.", data);
        }

        return true;
    }

    private sealed class UnitView(HostLinkConnection connection, HostLinkClientOptions options, int unitNumber, UnitModels models, CompoundReadRegistry compoundReads)
        : HostLinkUnit(connection, options, unitNumber, models, compoundReads);
}
