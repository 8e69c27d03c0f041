namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The PLC clock as 0701 CLOCK READ returns it: year month day hour minute second day-of-week, one BCD byte each.
/// Two-digit years 70–99 are 1970–1999, 00–69 are 2000–2069. Day of week: 00 Sunday … 06 Saturday.
/// </summary>
public readonly struct FinsClock : IEquatable<FinsClock>
{
    /// <summary>Bytes of the response data.</summary>
    internal const int Length = 7;

    /// <summary>The first year a two-digit year can stand for.</summary>
    public const int MinYear = 1970;

    /// <summary>The last year a two-digit year can stand for.</summary>
    public const int MaxYear = 2069;

    /// <summary>Creates the clock value.</summary>
    /// <param name="time">The date and time (to the second).</param>
    /// <param name="dayOfWeek">The day of week the PLC reports (it may disagree with the date; it is kept as it is).</param>
    /// <exception cref="ArgumentOutOfRangeException">The year is outside 1970–2069.</exception>
    public FinsClock(DateTime time, DayOfWeek dayOfWeek)
    {
        CheckYear(time.Year, nameof(time));
        if ((uint)dayOfWeek > 6)
        {
            throw new ArgumentOutOfRangeException(nameof(dayOfWeek), dayOfWeek, "Not a day of week.");
        }

        Time = new DateTime(time.Year, time.Month, time.Day, time.Hour, time.Minute, time.Second, time.Kind);
        DayOfWeek = dayOfWeek;
    }

    /// <summary>Creates the clock value with the day of week of the date.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The year is outside 1970–2069.</exception>
    public FinsClock(DateTime time)
        : this(time, time.DayOfWeek)
    {
    }

    /// <summary>The date and time (no time zone: the PLC's local time).</summary>
    public DateTime Time { get; }

    /// <summary>The day of week the PLC reported.</summary>
    public DayOfWeek DayOfWeek { get; }

    /// <summary>Decodes the 7 bytes of response data.</summary>
    /// <exception cref="HostLinkFrameException">
    /// <see cref="FrameError.WrongLength"/> when not 7 bytes; <see cref="FrameError.Malformed"/> when a byte is not
    /// BCD or the date is impossible.
    /// </exception>
    internal static FinsClock Read(ReadOnlySpan<byte> data)
    {
        if (data.Length != Length)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"CLOCK READ data holds {data.Length} bytes; it should hold {Length}.");
        }

        Span<int> v = stackalloc int[Length];
        for (int i = 0; i < Length; i++)
        {
            if (!FinsBytes.TryFromBcd(data[i], out v[i]))
            {
                throw new HostLinkFrameException(FrameError.Malformed, $"CLOCK READ byte {i} ({data[i]:X2}) is not BCD.");
            }
        }

        if (!TryCreate(v[0], v[1], v[2], v[3], v[4], v[5], out DateTime time) || v[6] > 6)
        {
            throw new HostLinkFrameException(FrameError.Malformed, "CLOCK READ returned an impossible date, time or day of week.");
        }

        return new FinsClock(time, (DayOfWeek)v[6]);
    }

    /// <summary>Encodes the 7 bytes of response data.</summary>
    /// <returns><see cref="Length"/>.</returns>
    internal int Write(Span<byte> destination)
    {
        if (destination.Length < Length)
        {
            throw new ArgumentException("The destination is too small for the clock.", nameof(destination));
        }

        destination[0] = FinsBytes.ToBcd(Time.Year % 100);
        destination[1] = FinsBytes.ToBcd(Time.Month);
        destination[2] = FinsBytes.ToBcd(Time.Day);
        destination[3] = FinsBytes.ToBcd(Time.Hour);
        destination[4] = FinsBytes.ToBcd(Time.Minute);
        destination[5] = FinsBytes.ToBcd(Time.Second);
        destination[6] = FinsBytes.ToBcd((int)DayOfWeek);
        return Length;
    }

    /// <summary>The full year of a two-digit year: 70–99 → 1970–1999, 00–69 → 2000–2069.</summary>
    internal static int ExpandYear(int twoDigitYear)
    {
        Guard.InRange(twoDigitYear, 0, 99);
        return twoDigitYear >= 70 ? 1900 + twoDigitYear : 2000 + twoDigitYear;
    }

    /// <inheritdoc/>
    public bool Equals(FinsClock other) => Time == other.Time && DayOfWeek == other.DayOfWeek;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is FinsClock other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => Time.GetHashCode() ^ (int)DayOfWeek;

    /// <summary>The time in ISO 8601 form and the day of week.</summary>
    public override string ToString() => $"{Time:yyyy-MM-dd HH:mm:ss} {DayOfWeek}";

    /// <summary>Equality.</summary>
    public static bool operator ==(FinsClock left, FinsClock right) => left.Equals(right);

    /// <summary>Inequality.</summary>
    public static bool operator !=(FinsClock left, FinsClock right) => !left.Equals(right);

    internal static void CheckYear(int year, string name)
    {
        if (year < MinYear || year > MaxYear)
        {
            throw new ArgumentOutOfRangeException(name, year, $"The PLC clock holds two-digit years, i.e. {MinYear}-{MaxYear}; {year} cannot be sent.");
        }
    }

    /// <summary>Builds a date from decoded BCD fields; false when it is impossible.</summary>
    internal static bool TryCreate(int yy, int month, int day, int hour, int minute, int second, out DateTime time)
    {
        time = default;
        int year = ExpandYear(yy);
        if (month is < 1 or > 12 || day < 1 || day > DateTime.DaysInMonth(year, month) || hour > 23 || minute > 59 || second > 59)
        {
            return false;
        }

        time = new DateTime(year, month, day, hour, minute, second, DateTimeKind.Unspecified);
        return true;
    }
}
