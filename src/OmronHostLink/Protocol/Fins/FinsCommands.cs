using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The rows of the FINS commands without parameters, and those commands as ready instances (<see cref="SimpleFinsCommand"/>).
/// The rows of commands with parameters live beside their command types (<see cref="MemoryAreaReadCommand.CommandRow"/>, …).
/// </summary>
internal static class FinsCommands
{
    /// <summary>0601 CPU UNIT STATUS READ: operating status, mode and errors (<see cref="FinsCpuStatus"/>).</summary>
    public static FinsCommandRow CpuUnitStatusRead { get; } = Simple(0x0601, "CPU UNIT STATUS READ", CommandEffect.ReadOnly, FinsCpuStatus.Length,
            static (_, plc) =>
            {
                PlcErrorInfo errors = plc.Errors;
                string? message = plc.FalMessage;
                var status = new FinsCpuStatus(
                    plc.Mode == PlcMode.Program ? (byte)0x00 : (byte)0x01,
                    FinsCpuStatus.ModeOf(plc.Mode),
                    errors.FirstWord,
                    errors.SecondWord,
                    message is null ? (ushort)0 : (ushort)0x0001,
                    0,
                    message ?? string.Empty);
                var data = new byte[FinsCpuStatus.Length];
                status.Write(data);
                return FinsReply.Ok(data);
            },
            static (data, fields) =>
            {
                FinsCpuStatus status = FinsCpuStatus.Read(data);
                fields.Field("running", status.IsRunning);
                fields.Field("mode", FinsCpuStatus.ModeName(status.Mode));
                fields.Field("fatalErrors", (long)status.FatalErrors);
                fields.Field("nonFatalErrors", (long)status.NonFatalErrors);
                fields.Field("messages", (long)status.Messages);
                fields.Field("falNumber", (long)status.FalNumber);
                fields.Field("errorMessage", status.ErrorMessage);
            });

    /// <summary>0701 CLOCK READ: the PLC's date and time (<see cref="FinsClock"/>).</summary>
    public static FinsCommandRow ClockRead { get; } = Simple(0x0701, "CLOCK READ", CommandEffect.ReadOnly, FinsClock.Length,
            static (_, plc) =>
            {
                var data = new byte[FinsClock.Length];
                new FinsClock(plc.Clock).Write(data);
                return FinsReply.Ok(data);
            },
            static (data, fields) =>
            {
                FinsClock clock = FinsClock.Read(data);
                fields.Field("clock", clock.Time.ToString("yyyy-MM-dd HH:mm:ss", CultureInfo.InvariantCulture));
                fields.Field("dayOfWeek", clock.DayOfWeek.ToString());
            });

    /// <summary>2302 FORCED SET/RESET CANCEL: releases every forced bit; refused in RUN mode (2206), as C-mode's KC is.</summary>
    public static FinsCommandRow ForcedCancel { get; } = Simple(0x2302, "FORCED SET/RESET CANCEL", CommandEffect.NotRepeatable, 0,
            static (_, plc) =>
            {
                if (plc.Mode == PlcMode.Run)
                {
                    return FinsReply.Code(FinsEndCodes.NotExecutableInRunMode);
                }

                plc.ReleaseAllForced();
                return FinsReply.Done;
            },
            describeAnswer: null);

    /// <summary>The 0601 command.</summary>
    public static FinsCommand CpuUnitStatusReadCommand { get; } = new SimpleFinsCommand(CpuUnitStatusRead);

    /// <summary>The 0701 command.</summary>
    public static FinsCommand ClockReadCommand { get; } = new SimpleFinsCommand(ClockRead);

    /// <summary>The 2302 command.</summary>
    public static FinsCommand ForcedCancelCommand { get; } = new SimpleFinsCommand(ForcedCancel);

    /// <summary>A row of a command without parameters: it refuses any parameter byte (1001).</summary>
    private static FinsCommandRow Simple(ushort code, string name, CommandEffect effect, int maxResponseData, FinsExecute execute, FinsDescribeAnswer? describeAnswer)
    {
        FinsCommandRow row = null!;
        row = new FinsCommandRow(code, name, effect, maxResponseData)
        {
            Parse = parameters =>
            {
                FinsCommand.CheckLength(code, parameters, 0, 0);
                return new SimpleFinsCommand(row);
            },
            Execute = execute,
            DescribeAnswer = describeAnswer,
        };
        return row;
    }
}
