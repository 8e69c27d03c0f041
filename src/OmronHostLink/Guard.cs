using System.Diagnostics.CodeAnalysis;
using System.Runtime.CompilerServices;

namespace OmronHostLink;

/// <summary>Argument guards that work the same on every target framework.</summary>
internal static class Guard
{
    public static T NotNull<T>([NotNull] T? value, [CallerArgumentExpression(nameof(value))] string? name = null)
        where T : class
        => value ?? throw new ArgumentNullException(name);

    public static void InRange(int value, int min, int max, [CallerArgumentExpression(nameof(value))] string? name = null)
    {
        if (value < min || value > max)
        {
            throw new ArgumentOutOfRangeException(name, value, $"{name} must be between {min} and {max}; it was {value}.");
        }
    }

    public static void Unit(int unit, [CallerArgumentExpression(nameof(unit))] string? name = null)
    {
        if (SettingRules.UnitNumber(unit) is { } problem)
        {
            throw new ArgumentOutOfRangeException(name, unit, $"The Host Link unit: {problem}.");
        }
    }
}
