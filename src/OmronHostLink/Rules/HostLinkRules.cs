namespace OmronHostLink;

/// <summary>
/// The rules of Host Link itself that an application checks its own configuration against, each written once: the unit
/// numbers a Host Link line addresses. The client, the simulator, the gateway and the components all ask here.
/// </summary>
public static class HostLinkRules
{
    /// <summary>The highest unit number Host Link addresses (two decimal digits after <c>@</c>, 00-31).</summary>
    public const int MaxUnitNumber = 31;

    /// <summary>Whether <paramref name="unit"/> is a Host Link unit number, 0-31.</summary>
    /// <param name="unit">The unit number.</param>
    /// <returns>True for 0-31.</returns>
    public static bool IsUnitNumber(int unit) => unit is >= 0 and <= MaxUnitNumber;

    /// <summary>What is wrong with <paramref name="unit"/> as a unit number, in the writer's words, or null when it is one.</summary>
    /// <param name="unit">The unit number.</param>
    /// <returns><c>32 is not a unit number (0-31)</c>, or null.</returns>
    public static string? CheckUnitNumber(int unit) => IsUnitNumber(unit) ? null : $"{unit} is not a unit number (0-{MaxUnitNumber})";
}
