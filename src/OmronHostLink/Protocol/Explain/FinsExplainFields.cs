using System.Globalization;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Protocol.Explain;

/// <summary>
/// The fields of a FINS command's parameters and of the answer data that describes itself, for <c>explain</c>, from the
/// library's typed commands (<see cref="FinsCommand.Parse"/>) and answer decoders.
/// </summary>
internal static class FinsExplainFields
{
    /// <summary>Adds the parameters of <paramref name="command"/>; a command this library does not model adds none.</summary>
    public static void AddParameters(FrameExplanation x, FinsCommand command)
    {
        switch (command)
        {
            case MemoryAreaReadCommand read:
                AddAddress(x, read.Address);
                x.Field("count", (long)read.Count);
                break;
            case MemoryAreaWriteCommand write:
                AddAddress(x, write.Address);
                x.Field("count", (long)write.Count);
                AddElements(x, write.Address, write.Data.Span);
                break;
            case MemoryAreaFillCommand fill:
                AddAddress(x, fill.Address);
                x.Field("count", (long)fill.Count);
                x.Field("value", (long)fill.Value);
                break;
            case MultipleMemoryAreaReadCommand multiple:
                x.Field("items", multiple.Items.Select(a => FinsAddressField.Of(a)).ToArray());
                break;
            case MemoryAreaTransferCommand transfer:
                x.Field("source", FinsAddressField.Of(transfer.Source));
                x.Field("destination", FinsAddressField.Of(transfer.Destination));
                x.Field("count", (long)transfer.Count);
                break;
            case RunCommand run:
                x.Field("programNumber", run.ProgramNumber is { } program ? Hex(program) : null);
                x.Field("mode", run.Mode is { } mode ? ModeName(mode) : null);
                break;
            case StopCommand stop:
                x.Field("programNumber", stop.ProgramNumber is { } stopped ? Hex(stopped) : null);
                break;
            case CpuUnitDataReadCommand data:
                x.Field("selector", data.Selector is { } selector ? selector.ToString("X2", CultureInfo.InvariantCulture) : null);
                break;
            case CycleTimeReadCommand cycle:
                x.Field("initialize", cycle.Initialize);
                break;
            case ClockWriteCommand clock:
                x.Field("clock", clock.Time.ToString(clock.IncludesSecond ? "yyyy-MM-dd HH:mm:ss" : "yyyy-MM-dd HH:mm", CultureInfo.InvariantCulture));
                x.Field("dayOfWeek", clock.DayOfWeek?.ToString());
                break;
            case ErrorClearCommand clear:
                x.Field("errorCode", Hex(clear.ErrorCode));
                break;
            case ErrorLogReadCommand log:
                x.Field("firstRecord", (long)log.FirstRecord);
                x.Field("count", (long)log.Count);
                break;
            case ForcedSetResetCommand force:
                x.Field("items", force.Items.Select(i => FinsAddressField.Of(i.Address, i.Action.ToString())).ToArray());
                break;
        }
    }

    /// <summary>Adds the answer data of the commands whose data describes itself: 0501, 0601 and 0701.</summary>
    /// <exception cref="HostLinkFrameException">The data does not have the answer's length.</exception>
    public static void AddAnswerData(FrameExplanation x, ushort commandCode, ReadOnlySpan<byte> data)
    {
        switch (commandCode)
        {
            case CpuUnitDataReadCommand.Code:
                FinsCpuUnitData unit = FinsCpuUnitData.Read(data);
                x.Field("model", unit.Model);
                x.Field("version", unit.Version);
                break;
            case CpuUnitStatusReadCommand.Code:
                FinsCpuStatus status = FinsCpuStatus.Read(data);
                x.Field("running", status.IsRunning);
                x.Field("mode", ModeName(status.Mode));
                x.Field("fatalErrors", (long)status.FatalErrors);
                x.Field("nonFatalErrors", (long)status.NonFatalErrors);
                x.Field("messages", (long)status.Messages);
                x.Field("falNumber", (long)status.FalNumber);
                x.Field("errorMessage", status.ErrorMessage);
                break;
            case ClockReadCommand.Code:
                FinsClock clock = FinsClock.Read(data);
                x.Field("clock", clock.Time.ToString("yyyy-MM-dd HH:mm:ss", CultureInfo.InvariantCulture));
                x.Field("dayOfWeek", clock.DayOfWeek.ToString());
                break;
        }
    }

    private static void AddAddress(FrameExplanation x, FinsMemoryAddress address)
    {
        FinsAddressField field = FinsAddressField.Of(address);
        x.Field("areaCode", field.AreaCode);
        x.Field("area", field.Area);
        x.Field("address", field.Address);
        x.Field("word", field.Word);
        x.Field("bit", field.Bit);
    }

    /// <summary>The write data as words (2-byte elements) or bits (bit areas); other element sizes stay in <c>parameters</c>.</summary>
    private static void AddElements(FrameExplanation x, FinsMemoryAddress address, ReadOnlySpan<byte> data)
    {
        if (address.IsBit)
        {
            x.Field("bits", data.ToArray().Select(b => b != 0).ToArray());
        }
        else if (address.ElementSize == 2)
        {
            x.Field("words", FinsWords.Read(data, data.Length / 2).Select(w => (long)w).ToArray());
        }
    }

    private static string ModeName(FinsCpuMode mode)
        => Enum.IsDefined(mode) ? mode.ToString().ToUpperInvariant() : $"unknown mode {(byte)mode:X2}";

    private static string Hex(ushort value) => value.ToString("X4", CultureInfo.InvariantCulture);
}
