using System.Text.RegularExpressions;

namespace OmronHostLink;

/// <summary>
/// What a refusal says when C-mode cannot do a job FINS can: exactly how to switch, in code. One home for the words,
/// so every "use FINS" reads alike and a host can say it in its own terms (the console: <c>--fins</c>).
/// </summary>
internal static class CommandSetAdvice
{
    private const string Head = "use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, or go through a FINS view of the unit, ";
    private const string AnyUnit = "such as plc.Unit(0, HostLinkCommandSet.Fins)";

    private static readonly Regex Advice = new(
        Regex.Escape(Head) + "(" + Regex.Escape(AnyUnit) + @"|plc\.Unit\(\d+, HostLinkCommandSet\.Fins\))",
        RegexOptions.CultureInvariant);

    /// <summary>How to switch to FINS, for a refusal that does not know the unit (an address check).</summary>
    public static string UseFins() => Head + AnyUnit;

    /// <summary>How to switch to FINS for unit <paramref name="unit"/>.</summary>
    public static string UseFins(int unit) => Head + $"plc.Unit({unit}, HostLinkCommandSet.Fins)";

    /// <summary>How to switch to C-mode, for a model that takes no FINS over Host Link.</summary>
    public const string UseCMode = "use C-mode: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.CMode (the default), or go through a C-mode view of the unit, such as plc.Unit(0, HostLinkCommandSet.CMode)";

    /// <summary>How to write bits with C-mode all the same, and what it costs.</summary>
    public static string ReadModifyWrite(string words)
        => $"or set HostLinkClientOptions.AllowReadModifyWriteBits = true to read {words}, change the bits and write {words} back (anything the PLC program writes there in between is lost)";

    /// <summary>
    /// The advice of <paramref name="message"/> in a host's own words: <paramref name="useFins"/> for "use FINS" (the
    /// console's <c>add --fins</c>), <paramref name="useCMode"/> for "use C-mode" (<c>leave out --fins</c>).
    /// </summary>
    public static string Replace(string message, string useFins, string useCMode)
        => Advice.Replace(message, useFins).Replace(UseCMode, useCMode);
}
