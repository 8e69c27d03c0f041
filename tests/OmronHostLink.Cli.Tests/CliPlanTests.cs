using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// <c>plan</c> shows the reads a set of tags takes and their time at the line's speed, without a PLC: the planner's own
/// plan, with QQ where the model (given, or to be named by MM) has it.
/// </summary>
public sealed class CliPlanTests
{
    private static readonly string[] Scattered = ["D100", "D200", "D300", "D400:float", "CIO10.03", "T5:bit"];

    [Fact]
    public async Task Plan_with_a_model_that_has_QQ_reads_the_scattered_words_with_one_QQIR()
    {
        CliResult r = await Cli.RunAsync(["plan", .. Scattered, "--model", "CS1", "--interval", "1s"]);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Lines()[0].Should().Be("6 tag(s), C-mode, 9600 bps, 11 bits/char, UseCompoundRead Auto, CS1/CJ1/CJ2:");
        r.Lines()[1].Should().MatchRegex(@"^2 reads \(1 QQIR of 6 items, 1 C-mode RG read\), \d+ characters, \d+ ms at 9600 bps — \d+ % of a 1 s interval$");
        r.Out.Should().Contain("unit 00 C-mode QQIR × 6").And.Contain("unit 00 C-mode RG T5 × 1 flags");
    }

    [Fact]
    public async Task Plan_with_a_model_without_QQ_or_with_QQ_off_reads_by_area()
    {
        CliResult cp2e = await Cli.RunAsync(["plan", .. Scattered, "--model", "CP2E", "--json"]);
        CliResult off = await Cli.RunAsync(["plan", .. Scattered, "--compound-read", "off", "--json"]);

        foreach (CliResult r in new[] { cp2e, off })
        {
            r.ExitCode.Should().Be(0, r.ToString());
            JsonElement plan = r.Json().GetProperty("plan");
            plan.GetProperty("commands").EnumerateArray().Select(c => c.GetProperty("kind").GetString()).Should().OnlyContain(k => k == "CModeArea" || k == "CModeCompletionFlags");
            r.Json().TryGetProperty("withCompoundRead", out _).Should().BeFalse();
        }
    }

    [Fact]
    public async Task Plan_without_a_model_shows_the_area_reads_until_the_PLC_names_its_model_and_the_QQ_plan_after()
    {
        CliResult r = await Cli.RunAsync(["plan", .. Scattered, "--interval", "100ms"]);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Lines()[1].Should().StartWith("6 reads (5 C-mode area reads, 1 C-mode RG read)").And.Contain("of a 100 ms interval: more than it, read every");
        r.Out.Should().Contain("Once the PLC names its model (MM), and where that model has QQ: 2 reads (1 QQIR of 6 items, 1 C-mode RG read)");
    }

    [Fact]
    public async Task Plan_reads_tags_from_a_file_and_names_a_bad_line()
    {
        string file = Path.GetTempFileName();
        try
        {
            await File.WriteAllLinesAsync(file, ["# a comment", "D100", "", "D200:int16  # a trailing comment", "D3OO"]);
            CliResult bad = await Cli.RunAsync("plan", "--file", file);
            bad.ExitCode.Should().Be(2, bad.ToString());
            bad.Err.Should().Contain($"{file}, line 5: ");

            await File.WriteAllLinesAsync(file, ["# a comment", "D100", "", "D200:int16  # a trailing comment"]);
            CliResult good = await Cli.RunAsync("plan", "--file", file, "--compound-read", "off");
            good.ExitCode.Should().Be(0, good.ToString());
            good.Lines()[0].Should().StartWith("2 tag(s), C-mode");
        }
        finally
        {
            File.Delete(file);
        }
    }

    [Fact]
    public async Task Compound_read_is_an_option_of_monitor_and_a_bad_value_is_a_usage_error()
    {
        CliResult r = await Cli.RunAsync("monitor", "D0", "--compound-read", "sometimes", "--tcp", "127.0.0.1:9");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--compound-read: 'sometimes' is not one of auto, on, off");
    }
}
