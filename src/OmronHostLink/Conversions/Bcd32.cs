using System.Globalization;

namespace OmronHostLink;

/// <summary>
/// A number 0–99999999 that the PLC stores as 8 BCD digits in two words (12345678 ↔ 0x5678, 0x1234 with Omron's low
/// word first; see <see cref="WordOrder"/>), as the double-length BCD instructions do. The type argument that makes the
/// generic reads and writes (<c>ReadAsync&lt;Bcd32&gt;</c>) use 8-digit BCD; read the raw value with <see cref="uint"/> instead.
/// </summary>
public readonly struct Bcd32 : IEquatable<Bcd32>, IComparable<Bcd32>
{
    /// <summary>The largest value: 99999999.</summary>
    public const int MaxValue = PlcWords.MaxBcd32;

    /// <summary>Creates the value.</summary>
    /// <param name="value">0–99999999.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 99999999.</exception>
    public Bcd32(int value)
    {
        if (value < 0 || value > MaxValue)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, $"two BCD words can hold 0–{MaxValue}; {value} does not fit.");
        }

        Value = value;
    }

    /// <summary>The number, 0–99999999.</summary>
    public int Value { get; }

    /// <summary>Converts a number 0–99999999.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 99999999.</exception>
    public static explicit operator Bcd32(int value) => new(value);

    /// <summary>The number.</summary>
    public static implicit operator int(Bcd32 value) => value.Value;

    /// <summary>Whether two values are equal.</summary>
    public static bool operator ==(Bcd32 left, Bcd32 right) => left.Value == right.Value;

    /// <summary>Whether two values differ.</summary>
    public static bool operator !=(Bcd32 left, Bcd32 right) => left.Value != right.Value;

    /// <summary>Whether <paramref name="left"/> is less than <paramref name="right"/>.</summary>
    public static bool operator <(Bcd32 left, Bcd32 right) => left.Value < right.Value;

    /// <summary>Whether <paramref name="left"/> is greater than <paramref name="right"/>.</summary>
    public static bool operator >(Bcd32 left, Bcd32 right) => left.Value > right.Value;

    /// <summary>Whether <paramref name="left"/> is less than or equal to <paramref name="right"/>.</summary>
    public static bool operator <=(Bcd32 left, Bcd32 right) => left.Value <= right.Value;

    /// <summary>Whether <paramref name="left"/> is greater than or equal to <paramref name="right"/>.</summary>
    public static bool operator >=(Bcd32 left, Bcd32 right) => left.Value >= right.Value;

    /// <summary>Creates the value from a number 0–99999999 (the named form of the explicit conversion).</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 99999999.</exception>
    public static Bcd32 FromInt32(int value) => new(value);

    /// <summary>The number (the named form of the implicit conversion).</summary>
    public int ToInt32() => Value;

    /// <inheritdoc/>
    public int CompareTo(Bcd32 other) => Value.CompareTo(other.Value);

    /// <inheritdoc/>
    public bool Equals(Bcd32 other) => Value == other.Value;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is Bcd32 other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => Value;

    /// <summary>The number in decimal, invariant culture.</summary>
    public override string ToString() => Value.ToString(CultureInfo.InvariantCulture);
}
