
namespace OmronHostLink.Tests.Fins;

/// <summary>Selections of the FINS-over-Host-Link golden vectors.</summary>
public static class FinsVectors
{
    public static bool IsFins(Vector v) => GoldenVectors.NameStartsWith(v, "f_", "cs_fins_", "java_fins_", "hsl_fins_", "fieldlink_fins_");

    public static IEnumerable<object[]> GoodCommands => GoldenVectors.Names(v => IsFins(v) && v.IsCommand && v.FcsOk);

    public static IEnumerable<object[]> GoodResponses => GoldenVectors.Names(v => IsFins(v) && v.IsResponse && v.FcsOk);

    /// <summary>Good responses that carry a FINS part (all but the Host Link-level rejection).</summary>
    public static IEnumerable<object[]> GoodFinsResponses => GoldenVectors.Names(v => IsFins(v) && v.IsResponse && v.FcsOk && v.Name != "f_hl_err_14");

    public static IEnumerable<object[]> BadFcs => GoldenVectors.Names(v => IsFins(v) && !v.FcsOk);
}
