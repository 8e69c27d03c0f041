using System.Globalization;

namespace OmronHostLink;

/// <summary>
/// A number 0–9999 that the PLC stores as one word of 4 BCD digits (1234 ↔ 0x1234), as timers, counters and many
/// settings do. The type argument that makes the generic reads and writes (<c>ReadAsync&lt;Bcd16&gt;</c>) use BCD;
/// read the raw word with <see cref="ushort"/> instead.
/// </summary>
public readonly struct Bcd16 : IEquatable<Bcd16>, IComparable<Bcd16>
{
    /// <summary>The largest value: 9999.</summary>
    public const int MaxValue = PlcWords.MaxBcd;

    /// <summary>Creates the value.</summary>
    /// <param name="value">0–9999.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 9999.</exception>
    public Bcd16(int value)
    {
        if (value < 0 || value > MaxValue)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, $"one BCD word can hold 0–{MaxValue}; {value} does not fit.");
        }

        Value = value;
    }

    /// <summary>The number, 0–9999.</summary>
    public int Value { get; }

    /// <summary>Converts a number 0–9999.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 9999.</exception>
    public static explicit operator Bcd16(int value) => new(value);

    /// <summary>The number.</summary>
    public static implicit operator int(Bcd16 value) => value.Value;

    /// <summary>Whether two values are equal.</summary>
    public static bool operator ==(Bcd16 left, Bcd16 right) => left.Value == right.Value;

    /// <summary>Whether two values differ.</summary>
    public static bool operator !=(Bcd16 left, Bcd16 right) => left.Value != right.Value;

    /// <summary>Whether <paramref name="left"/> is less than <paramref name="right"/>.</summary>
    public static bool operator <(Bcd16 left, Bcd16 right) => left.Value < right.Value;

    /// <summary>Whether <paramref name="left"/> is greater than <paramref name="right"/>.</summary>
    public static bool operator >(Bcd16 left, Bcd16 right) => left.Value > right.Value;

    /// <summary>Whether <paramref name="left"/> is less than or equal to <paramref name="right"/>.</summary>
    public static bool operator <=(Bcd16 left, Bcd16 right) => left.Value <= right.Value;

    /// <summary>Whether <paramref name="left"/> is greater than or equal to <paramref name="right"/>.</summary>
    public static bool operator >=(Bcd16 left, Bcd16 right) => left.Value >= right.Value;

    /// <summary>Creates the value from a number 0–9999 (the named form of the explicit conversion).</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 9999.</exception>
    public static Bcd16 FromInt32(int value) => new(value);

    /// <summary>The number (the named form of the implicit conversion).</summary>
    public int ToInt32() => Value;

    /// <inheritdoc/>
    public int CompareTo(Bcd16 other) => Value.CompareTo(other.Value);

    /// <inheritdoc/>
    public bool Equals(Bcd16 other) => Value == other.Value;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is Bcd16 other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => Value;

    /// <summary>The number in decimal, invariant culture.</summary>
    public override string ToString() => Value.ToString(CultureInfo.InvariantCulture);
}
