using System.Text.RegularExpressions;

namespace OmronHostLink.Com.Tests;

/// <summary>
/// The VB6 and VBA examples of docs/migrating.md cannot be compiled here, so each is held to what can be run: every
/// <c>plc.Member</c> they call, every <c>plc_Event</c> handler and every <c>ohlErr…</c> constant must be in the type
/// library's IDL, and every member and event must be used by the VBScript tests that run against the simulator.
/// </summary>
public sealed partial class DocumentationTests
{
    private static readonly string Idl = File.ReadAllText(Path.Combine(WineBed.Root, "src", "OmronHostLink.Com", "OmronHostLink.Com.idl"));

    [Fact]
    public void The_VB6_and_VBA_examples_call_what_the_tested_scripts_call()
    {
        string[] blocks = VbaBlocks();
        blocks.Should().HaveCountGreaterThanOrEqualTo(3, "the guide has a VBA module, a VB6 form and the polling loop");
        string code = string.Join('\n', blocks);
        string scripts = string.Join('\n', Directory.GetFiles(Path.Combine(AppContext.BaseDirectory, "Scripts"), "*.vbs").Select(File.ReadAllText));

        string[] members = MemberCall().Matches(code).Select(m => m.Groups[1].Value).Distinct().ToArray();
        members.Should().Contain(["Open", "ReadWords", "ReadReal", "ReadBcd", "ReadMode", "WriteWord", "Close", "Watch", "WaitForChanges", "WatchedValue"]);
        foreach (string member in members)
        {
            IdlMembers().Should().Contain(member, $"plc.{member} in docs/migrating.md must be a member of IPlc");
            scripts.Should().MatchRegex($@"plc\.{member}\b", $"plc.{member} in docs/migrating.md must be called by a tested script");
        }

        string[] events = EventHandler().Matches(code).Select(m => m.Groups[1].Value).Distinct().ToArray();
        events.Should().BeEquivalentTo(["ValueChanged", "ConnectionLost", "ConnectionRestored"]);
        foreach (string name in events)
        {
            Idl.Should().MatchRegex($@"\] void {name}\(", $"plc_{name} handles an event of IPlcEvents");
            scripts.Should().Contain($"Sub plc_{name}(", "the events script handles it");
        }

        foreach (string constant in Constant().Matches(string.Join('\n', File.ReadAllLines(Path.Combine(WineBed.Root, "docs", "migrating.md")))).Select(m => m.Value).Distinct())
        {
            Idl.Should().Contain(constant + " = ", $"{constant} in docs/migrating.md is a constant of the type library");
        }
    }

    private static IEnumerable<string> IdlMembers()
        => IdlMember().Matches(Idl[Idl.IndexOf("interface IPlc : IDispatch", StringComparison.Ordinal)..]).Select(m => m.Groups[1].Value);

    private static string[] VbaBlocks()
    {
        string[] lines = File.ReadAllLines(Path.Combine(WineBed.Root, "docs", "migrating.md"));
        var blocks = new List<string>();
        for (int i = 0; i < lines.Length; i++)
        {
            if (lines[i].Trim() != "```vba")
            {
                continue;
            }

            int end = Array.FindIndex(lines, i + 1, l => l.Trim() == "```");
            blocks.Add(string.Join('\n', lines[(i + 1)..end]));
            i = end;
        }

        return blocks.ToArray();
    }

    [GeneratedRegex(@"\bplc\.(\w+)")]
    private static partial Regex MemberCall();

    [GeneratedRegex(@"Sub plc_(\w+)\(")]
    private static partial Regex EventHandler();

    [GeneratedRegex(@"\bohlErr\w+")]
    private static partial Regex Constant();

    [GeneratedRegex(@"HRESULT (\w+)\(")]
    private static partial Regex IdlMember();
}
