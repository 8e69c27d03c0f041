namespace OmronHostLink.Com.Tests;

/// <summary>
/// A watch's events reach a script through WScript.ConnectObject, on the script's own thread, while it sleeps. Wine 8's
/// cscript answers ConnectObject and Sleep with "Object doesn't support this action" (E_NOTIMPL), so events.vbs runs
/// through the bed's scripthost (tests/OmronHostLink.Com.Tests/Native/scripthost.c), which does what Windows Script
/// Host does: the object's default source interface from IProvideClassInfo and the type library, a connection point
/// Advise, and each event calling the script's Sub plc_&lt;EventName&gt; by its name; it refuses an event that arrives on
/// another thread than the script's.
/// </summary>
[Collection(WineCollection.Name)]
public sealed class EventTests(WineBed bed)
{
    private static readonly TimeSpan Timeout = TimeSpan.FromMinutes(2);

    public static TheoryData<string> Architectures => VbScriptTests.Architectures;

    [SkippableTheory]
    [MemberData(nameof(Architectures))]
    public async Task ValueChanged_and_ConnectionLost_reach_a_script_through_ConnectObject(string architecture)
    {
        Skip.If(architecture == "x86" && bed.Wine32 is null, "No 32-bit Wine for the x86 server: " + bed.X86Status);
        await using Simulation simulation = await Simulation.StartAsync();
        string host = Path.Combine(bed.Tools, $"scripthost-{architecture}.exe");
        await using WineProcess script = bed.Launch(bed.WineFor(architecture), [host, WineBed.WindowsPath(VbScriptTests.ScriptPath("events.vbs")), simulation.Endpoint]);

        await script.WaitForLineAsync(l => l == "Ready=yes", Timeout, "Ready=yes");
        script.Lines.Should().Contain("ValueChanged=initial D100 1000");
        simulation.Unit0.WriteWords("D100", [777]);
        await script.WaitForLineAsync(l => l.StartsWith("Phase=", StringComparison.Ordinal), Timeout, "Phase=");
        script.Lines.Should().Contain("ValueChanged=ready D100 777").And.Contain("Phase=changed");

        await simulation.StopAsync();
        (await script.WaitForExitAsync(Timeout)).Should().Be(0, script.Output);
        // The first report names the loss (a watch that keeps failing while the script winds down may report again).
        string lost = script.Lines.First(l => l.StartsWith("ConnectionLost=", StringComparison.Ordinal));
        int number = int.Parse(lost["ConnectionLost=".Length..lost.IndexOf('|', StringComparison.Ordinal)], System.Globalization.CultureInfo.InvariantCulture);
        number.Should().BeOneOf(Documented.Connection, Documented.Timeout);
        script.Lines.Should().Contain("Phase=lost").And.Contain("Done=yes");
        script.Output.Should().NotContain("raised on thread");
    }
}
