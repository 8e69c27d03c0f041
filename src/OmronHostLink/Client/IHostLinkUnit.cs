using OmronHostLink.Planning;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>
/// What application code does with one PLC on a Host Link line: words, typed values, bits, text, planned tag reads,
/// change subscriptions, status, mode, errors, model, test and the FINS services. <see cref="HostLinkUnit"/> (and so
/// <see cref="HostLinkClient"/>) implements it; depend on this interface to test application code with a test double
/// instead of a wire.
/// </summary>
/// <remarks>
/// Addresses are CX-Programmer strings (<c>D100</c>, <c>CIO10.03</c>, <c>E1_200</c>). Typed values go through the
/// generic members; the per-type shortcuts of <see cref="HostLinkUnit"/> (<c>ReadInt32Async</c> and the like), the
/// <see cref="PlcAddress"/> overloads, and line control (<c>AbortAsync</c>, <c>InitializeAsync</c>) are on the concrete
/// types only.
/// </remarks>
public interface IHostLinkUnit
{
    /// <inheritdoc cref="HostLinkUnit.UnitNumber"/>
    int UnitNumber { get; }

    /// <inheritdoc cref="HostLinkUnit.CommandSet"/>
    HostLinkCommandSet CommandSet { get; }

    /// <inheritdoc cref="HostLinkUnit.WordOrder"/>
    WordOrder WordOrder { get; }

    /// <inheritdoc cref="HostLinkUnit.Unit(int)"/>
    IHostLinkUnit Unit(int unitNumber);

    /// <inheritdoc cref="HostLinkUnit.Unit(int, HostLinkCommandSet)"/>
    IHostLinkUnit Unit(int unitNumber, HostLinkCommandSet commandSet);

    /// <inheritdoc cref="HostLinkUnit.WithWordOrder(WordOrder)"/>
    IHostLinkUnit WithWordOrder(WordOrder order);

    /// <inheritdoc cref="HostLinkUnit.ReadWordsAsync(string, int, CancellationToken)"/>
    Task<ushort[]> ReadWordsAsync(string address, int count, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.WriteWordsAsync(string, ReadOnlyMemory{ushort}, CancellationToken)"/>
    Task WriteWordsAsync(string address, ReadOnlyMemory<ushort> words, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadAsync{T}(string, CancellationToken)"/>
    Task<T> ReadAsync<T>(string address, CancellationToken cancellationToken = default)
        where T : struct;

    /// <inheritdoc cref="HostLinkUnit.ReadAsync{T}(string, int, CancellationToken)"/>
    Task<T[]> ReadAsync<T>(string address, int count, CancellationToken cancellationToken = default)
        where T : struct;

    /// <inheritdoc cref="HostLinkUnit.WriteAsync{T}(string, T, CancellationToken)"/>
    Task WriteAsync<T>(string address, T value, CancellationToken cancellationToken = default)
        where T : struct;

    /// <inheritdoc cref="HostLinkUnit.WriteAsync{T}(string, T[], CancellationToken)"/>
    Task WriteAsync<T>(string address, T[] values, CancellationToken cancellationToken = default)
        where T : struct;

    /// <inheritdoc cref="HostLinkUnit.WriteAsync{T}(string, ReadOnlyMemory{T}, CancellationToken)"/>
    Task WriteAsync<T>(string address, ReadOnlyMemory<T> values, CancellationToken cancellationToken = default)
        where T : struct;

    /// <inheritdoc cref="HostLinkUnit.ReadBitAsync(string, CancellationToken)"/>
    Task<bool> ReadBitAsync(string address, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.WriteBitAsync(string, bool, CancellationToken)"/>
    Task WriteBitAsync(string address, bool value, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadStringAsync(string, int, CancellationToken)"/>
    Task<string> ReadStringAsync(string address, int length, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.WriteStringAsync(string, string, CancellationToken)"/>
    Task WriteStringAsync(string address, string text, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadTagsAsync(IReadOnlyList{PlcTag}, CancellationToken)"/>
    Task<PlcTagValue[]> ReadTagsAsync(IReadOnlyList<PlcTag> tags, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadTagsAsync(IReadOnlyList{string}, CancellationToken)"/>
    Task<PlcTagValue[]> ReadTagsAsync(IReadOnlyList<string> tags, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadTagsAsync(ReadPlan, CancellationToken)"/>
    Task<PlcTagValue[]> ReadTagsAsync(ReadPlan plan, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.WatchAsync(IReadOnlyList{PlcTag}, TimeSpan, CancellationToken)"/>
    IAsyncEnumerable<WatchEvent> WatchAsync(IReadOnlyList<PlcTag> tags, TimeSpan interval, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.WatchAsync(IReadOnlyList{PlcTag}, WatchOptions, CancellationToken)"/>
    IAsyncEnumerable<WatchEvent> WatchAsync(IReadOnlyList<PlcTag> tags, WatchOptions options, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadScatteredAsync(IReadOnlyList{string}, CancellationToken)"/>
    Task<ushort[]> ReadScatteredAsync(IReadOnlyList<string> addresses, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadStatusAsync(CancellationToken)"/>
    Task<PlcStatus> ReadStatusAsync(CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.SetModeAsync(PlcMode, CancellationToken)"/>
    Task SetModeAsync(PlcMode mode, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadErrorsAsync(bool, CancellationToken)"/>
    Task<PlcErrorInfo> ReadErrorsAsync(bool clear = false, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadModelAsync(CancellationToken)"/>
    Task<PlcModel> ReadModelAsync(CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.TestAsync(string, CancellationToken)"/>
    Task<TimeSpan> TestAsync(string text = "OMRONHOSTLINK", CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadCpuUnitDataAsync(CancellationToken)"/>
    Task<FinsCpuUnitData> ReadCpuUnitDataAsync(CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadCpuStatusAsync(CancellationToken)"/>
    Task<FinsCpuStatus> ReadCpuStatusAsync(CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadCycleTimeAsync(bool, CancellationToken)"/>
    Task<FinsCycleTime?> ReadCycleTimeAsync(bool initialize = false, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadClockAsync(CancellationToken)"/>
    Task<FinsClock> ReadClockAsync(CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.WriteClockAsync(DateTime, CancellationToken)"/>
    Task WriteClockAsync(DateTime time, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.RunAsync(PlcMode, CancellationToken)"/>
    Task RunAsync(PlcMode mode = PlcMode.Monitor, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.StopAsync(CancellationToken)"/>
    Task StopAsync(CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ClearErrorsAsync(ushort, CancellationToken)"/>
    Task ClearErrorsAsync(ushort errorCode = 0xFFFF, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ReadErrorLogAsync(int, int, CancellationToken)"/>
    Task<FinsErrorLog> ReadErrorLogAsync(int firstRecord = 0, int count = 20, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.FillAsync(string, int, ushort, CancellationToken)"/>
    Task FillAsync(string address, int count, ushort value, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.TransferAsync(string, string, int, CancellationToken)"/>
    Task TransferAsync(string source, string destination, int count, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.ForceBitAsync(string, FinsForceAction, CancellationToken)"/>
    Task ForceBitAsync(string address, FinsForceAction action, CancellationToken cancellationToken = default);

    /// <inheritdoc cref="HostLinkUnit.CancelForcedBitsAsync(CancellationToken)"/>
    Task CancelForcedBitsAsync(CancellationToken cancellationToken = default);
}
