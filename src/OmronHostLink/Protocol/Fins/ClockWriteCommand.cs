using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0702 CLOCK WRITE: sets the PLC's clock. Parameters (BCD): year(2 digits) month day hour minute, then optionally
/// second, then optionally day of week (00 = Sunday … 06 = Saturday; only after the second).
/// </summary>
/// <remarks>Two-digit years follow <see cref="FinsClock"/>: 70–99 are 1970–1999, 00–69 are 2000–2069.</remarks>
internal sealed class ClockWriteCommand : FinsCommand
{
    /// <summary>The command code, 0702.</summary>
    public const ushort Code = 0x0702;

    /// <summary>The command's row: 0702 CLOCK WRITE.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "CLOCK WRITE", CommandEffect.NotRepeatable, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) =>
        {
            var write = (ClockWriteCommand)command;
            plc.Clock = write.IncludesSecond ? write.Time : write.Time.AddSeconds(plc.Clock.Second);
            return FinsReply.Done;
        },
        DescribeCommand = static (command, fields) =>
        {
            var clock = (ClockWriteCommand)command;
            fields.Field("clock", clock.Time.ToString(clock.IncludesSecond ? "yyyy-MM-dd HH:mm:ss" : "yyyy-MM-dd HH:mm", CultureInfo.InvariantCulture));
            fields.Field("dayOfWeek", clock.DayOfWeek?.ToString());
        },
    };

    /// <summary>Sets the clock to <paramref name="time"/> (to the second), with its day of week.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The year is outside 1970–2069.</exception>
    public ClockWriteCommand(DateTime time)
        : this(time, includeSecond: true, time.DayOfWeek)
    {
    }

    /// <summary>Sets the clock, choosing which optional fields are sent.</summary>
    /// <param name="time">The date and time (milliseconds are dropped; seconds too when <paramref name="includeSecond"/> is false).</param>
    /// <param name="includeSecond">Whether the second is sent.</param>
    /// <param name="dayOfWeek">The day of week sent, or null to send none (it can only follow the second).</param>
    /// <exception cref="ArgumentException">A day of week without the second.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The year is outside 1970–2069 or the day of week is not a day.</exception>
    public ClockWriteCommand(DateTime time, bool includeSecond, DayOfWeek? dayOfWeek)
    {
        FinsClock.CheckYear(time.Year, nameof(time));
        if (dayOfWeek is not null && !includeSecond)
        {
            throw new ArgumentException("CLOCK WRITE sends the day of week after the second; include the second to send a day of week.", nameof(dayOfWeek));
        }

        if (dayOfWeek is DayOfWeek day && (uint)day > 6)
        {
            throw new ArgumentOutOfRangeException(nameof(dayOfWeek), dayOfWeek, "Not a day of week.");
        }

        Time = new DateTime(time.Year, time.Month, time.Day, time.Hour, time.Minute, includeSecond ? time.Second : 0, time.Kind);
        IncludesSecond = includeSecond;
        DayOfWeek = dayOfWeek;
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 5 + (IncludesSecond ? 1 : 0) + (DayOfWeek is null ? 0 : 1);

    /// <summary>The date and time sent (seconds are 0 when not sent).</summary>
    public DateTime Time { get; }

    /// <summary>Whether the second is sent.</summary>
    public bool IncludesSecond { get; }

    /// <summary>The day of week sent, if any (sent as it is, even when it disagrees with the date).</summary>
    public DayOfWeek? DayOfWeek { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        destination[0] = FinsBytes.ToBcd(Time.Year % 100);
        destination[1] = FinsBytes.ToBcd(Time.Month);
        destination[2] = FinsBytes.ToBcd(Time.Day);
        destination[3] = FinsBytes.ToBcd(Time.Hour);
        destination[4] = FinsBytes.ToBcd(Time.Minute);
        if (IncludesSecond)
        {
            destination[5] = FinsBytes.ToBcd(Time.Second);
        }

        if (DayOfWeek is DayOfWeek day)
        {
            destination[6] = FinsBytes.ToBcd((int)day);
        }
    }

    internal static ClockWriteCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 5, 7);
        Span<int> values = stackalloc int[7];
        for (int i = 0; i < parameters.Length; i++)
        {
            if (!FinsBytes.TryFromBcd(parameters[i], out values[i]))
            {
                throw new FinsFormatException(FinsEndCodes.ParameterError, $"CLOCK WRITE byte {i} ({parameters[i]:X2}) is not BCD.");
            }
        }

        if (!FinsClock.TryCreate(values[0], values[1], values[2], values[3], values[4], values[5], out DateTime time))
        {
            throw new FinsFormatException(FinsEndCodes.ParameterError, "CLOCK WRITE carries an impossible date or time.");
        }

        DayOfWeek? day = null;
        if (parameters.Length == 7)
        {
            if (values[6] > 6)
            {
                throw new FinsFormatException(FinsEndCodes.ParameterError, $"CLOCK WRITE day of week {values[6]:D2} is not 00-06.");
            }

            day = (DayOfWeek)values[6];
        }

        return new ClockWriteCommand(time, parameters.Length >= 6, day);
    }
}
