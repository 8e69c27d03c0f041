using OmronHostLink.Link;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>FINS over Host Link (header FA): memory, CPU data and status, cycle time, clock, run/stop, errors, forcing.</summary>
public partial class HostLinkUnit
{
    /// <summary>Reads the CPU Unit's model and version (FINS 0501).</summary>
    public Task<FinsCpuUnitData> ReadCpuUnitDataAsync(CancellationToken cancellationToken = default)
        => FinsAsync(new CpuUnitDataReadCommand(), static (data, _) => FinsCpuUnitData.Read(data), 0, cancellationToken).AsTask();

    /// <summary>Reads the CPU Unit's status, mode, error flags and error message (FINS 0601).</summary>
    public Task<FinsCpuStatus> ReadCpuStatusAsync(CancellationToken cancellationToken = default)
        => FinsAsync(FinsCommands.CpuUnitStatusReadCommand, static (data, _) => FinsCpuStatus.Read(data), 0, cancellationToken).AsTask();

    /// <summary>Reads the average, longest and shortest cycle times (FINS 0620); <paramref name="initialize"/> restarts the measurement instead.</summary>
    public Task<FinsCycleTime?> ReadCycleTimeAsync(bool initialize = false, CancellationToken cancellationToken = default)
        => FinsAsync(new CycleTimeReadCommand(initialize), static (data, init) => init ? null : FinsCycleTime.Read(data), initialize, cancellationToken).AsTask();

    /// <summary>Reads the PLC's clock (FINS 0701).</summary>
    public Task<FinsClock> ReadClockAsync(CancellationToken cancellationToken = default)
        => FinsAsync(FinsCommands.ClockReadCommand, static (data, _) => FinsClock.Read(data), 0, cancellationToken).AsTask();

    /// <summary>Sets the PLC's clock (FINS 0702), seconds and day of week included.</summary>
    public async Task WriteClockAsync(DateTime time, CancellationToken cancellationToken = default)
        => await FinsNoDataAsync(new ClockWriteCommand(time, includeSecond: true, time.DayOfWeek), cancellationToken).ConfigureAwait(false);

    /// <summary>Starts the program in MONITOR or RUN mode (FINS 0401).</summary>
    public async Task RunAsync(PlcMode mode = PlcMode.Monitor, CancellationToken cancellationToken = default)
    {
        if (mode == PlcMode.Program)
        {
            throw new ArgumentException("RUN takes MONITOR or RUN; use StopAsync for PROGRAM mode.", nameof(mode));
        }

        var command = new RunCommand(mode == PlcMode.Run ? FinsCpuMode.Run : FinsCpuMode.Monitor);
        await FinsNoDataAsync(command, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Stops the program: PROGRAM mode (FINS 0402).</summary>
    public async Task StopAsync(CancellationToken cancellationToken = default)
        => await FinsNoDataAsync(new StopCommand(), cancellationToken).ConfigureAwait(false);

    /// <summary>Clears one error, or all with the default <c>FFFF</c> (FINS 2101).</summary>
    public async Task ClearErrorsAsync(ushort errorCode = ErrorClearCommand.AllErrors, CancellationToken cancellationToken = default)
        => await FinsNoDataAsync(new ErrorClearCommand(errorCode), cancellationToken).ConfigureAwait(false);

    /// <summary>Reads error log records (FINS 2102), up to 53 in one exchange.</summary>
    public Task<FinsErrorLog> ReadErrorLogAsync(int firstRecord = 0, int count = 20, CancellationToken cancellationToken = default)
    {
        var command = new ErrorLogReadCommand(firstRecord, count);
        return FinsAsync(command, static (data, _) => FinsErrorLog.Read(data), 0, cancellationToken).AsTask();
    }

    /// <summary>Writes <paramref name="value"/> to <paramref name="count"/> words (FINS 0103).</summary>
    public async Task FillAsync(string address, int count, ushort value, CancellationToken cancellationToken = default)
    {
        PlcAddress a = PlcAddress.Parse(address).AsWord();
        a.EnsureRange(count, HostLinkCommandSet.Fins, forWrite: true);
        await FinsNoDataAsync(new MemoryAreaFillCommand(FinsAddressing.Word(a), count, value), cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Copies <paramref name="count"/> words inside the PLC (FINS 0105).</summary>
    public async Task TransferAsync(string source, string destination, int count, CancellationToken cancellationToken = default)
    {
        PlcAddress from = PlcAddress.Parse(source).AsWord();
        PlcAddress to = PlcAddress.Parse(destination).AsWord();
        from.EnsureRange(count, HostLinkCommandSet.Fins, forWrite: false);
        to.EnsureRange(count, HostLinkCommandSet.Fins, forWrite: true);
        var command = new MemoryAreaTransferCommand(FinsAddressing.Word(from), FinsAddressing.Word(to), count);
        await FinsNoDataAsync(command, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>
    /// Reads scattered words and bits in one exchange, one FINS 0104 MULTIPLE MEMORY AREA READ, so the values are one
    /// snapshot: a word address gives its value, a bit address (or a timer/counter completion flag) 0 or 1. Raw words
    /// only, at most 135 addresses, FINS whatever this view's command set; for typed tags planned into the fewest
    /// exchanges, see <see cref="ReadTagsAsync(IReadOnlyList{Planning.PlcTag}, CancellationToken)"/>.
    /// </summary>
    public async Task<ushort[]> ReadScatteredAsync(IReadOnlyList<string> addresses, CancellationToken cancellationToken = default)
    {
        Guard.NotNull(addresses);
        var items = new FinsMemoryAddress[addresses.Count];
        for (int i = 0; i < items.Length; i++)
        {
            PlcAddress a = PlcAddress.Parse(addresses[i]);
            a.EnsureRange(1, HostLinkCommandSet.Fins, forWrite: false);
            items[i] = FinsAddressing.Item(a);
        }

        var command = new MultipleMemoryAreaReadCommand(items);
        FinsMultipleReadValue[] values = await FinsAsync(command, static (data, c) => FinsMultipleReadValue.ReadAll(data, c), command, cancellationToken).ConfigureAwait(false);
        return values.Select(v => v.Word).ToArray();
    }

    /// <summary>Force-sets, force-resets or releases one bit (FINS 2301).</summary>
    public async Task ForceBitAsync(string address, FinsForceAction action, CancellationToken cancellationToken = default)
    {
        PlcAddress a = PlcAddress.Parse(address);
        if (!a.IsBit && a.Area is not (PlcArea.Timer or PlcArea.Counter))
        {
            throw new ArgumentException($"{a} names a word; forcing takes a bit address.", nameof(address));
        }

        await FinsNoDataAsync(new ForcedSetResetCommand(action, FinsAddressing.Item(a)), cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Releases every forced bit (FINS 2302).</summary>
    public async Task CancelForcedBitsAsync(CancellationToken cancellationToken = default)
        => await FinsNoDataAsync(FinsCommands.ForcedCancelCommand, cancellationToken).ConfigureAwait(false);

    /// <summary>Sends one FINS command whose answer carries no data.</summary>
    internal async ValueTask FinsNoDataAsync(FinsCommand command, CancellationToken cancellationToken)
        => await FinsAsync(
            command,
            static (data, c) => data.IsEmpty ? true : throw new HostLinkFrameException(FrameError.WrongLength, $"The answer to FINS {c.Row} should carry no data but carried {data.Length} bytes."),
            command,
            cancellationToken).ConfigureAwait(false);

    /// <summary>Sends one FINS command in an FA frame and decodes the data of a successful answer.</summary>
    /// <remarks>How often it is repeated and how long its answer may be come from the command (<see cref="FinsCommand.Effect"/>, <see cref="FinsCommand.MaxResponseDataLength"/>).</remarks>
    internal ValueTask<TResult> FinsAsync<TState, TResult>(FinsCommand command, ResponseDecoder<TState, TResult> decodeData, TState state, CancellationToken cancellationToken)
    {
        // A model known to have no FINS over Host Link is not sent FA frames at all.
        if (Models.TryGet(UnitNumber, out PlcModelProfile? model) && model is not null)
        {
            model.EnsureFins();
        }

        FinsHeader header = FinsHeader.Direct(Connection.NextSid(), Options.FinsResponseWait);
        var message = new byte[FinsMessage.GetCommandLength(header, command)];
        FinsMessage.WriteCommand(message, UnitNumber, header, command);
        var request = new HostLinkRequest(UnitNumber, CModeCommands.Fins.Header, message, FinsMessage.GetExchange(message.Length, header, command.MaxResponseDataLength));
        return Connection.ExecuteAsync(
            request,
            RetriesFor(command.Effect),
            static (text, s) =>
            {
                FinsResponse response = FinsResponse.Parse(text, s.unit, s.header, s.code);
                if (!response.IsSuccess)
                {
                    throw new FinsEndCodeException(response.EndCode, s.code, s.unit);
                }

                return s.decodeData(response.Data.Span, s.state);
            },
            (decodeData, state, header, code: command.CommandCode, unit: UnitNumber),
            cancellationToken);
    }
}
