using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>explain</c> without <c>--response</c>: an answer is recognised from its shape; an ambiguous frame says so.</summary>
public sealed class CliExplainDirectionTests
{
    /// <summary>
    /// Response vectors whose characters are also a well-formed command, so no tool can tell the direction from the
    /// frame: SC with 00 (SC to PROGRAM, and SC's normal completion) and a TS echo (the same characters both ways).
    /// </summary>
    private static readonly string[] AmbiguousAnswers = ["roof_sc_resp_ok", "c_ts_resp"];

    /// <summary>Command vectors that are also a well-formed answer: SC 00/02/03 (end codes 00/02/03), MF 01 (end code 01), TS.</summary>
    private static readonly string[] AmbiguousCommands = ["c_sc_prog", "roof_sc_monitor", "ha_sc_run", "c_mf_cmd", "arduino_ts", "java_ts"];

    /// <summary>A public fixture that writes end code 13 as 0D: neither an SC mode nor a C-mode end code, so nothing says it is an answer.</summary>
    private const string Misencoded = "roof_sc_resp_0D_misencoded";

    public static IEnumerable<object[]> UnambiguousAnswers
        => GoldenVectors.Names(v => v.IsResponse && !AmbiguousAnswers.Contains(v.Name) && v.Name != Misencoded);

    public static IEnumerable<object[]> Commands => GoldenVectors.Names(v => v.IsCommand);

    public static IEnumerable<object[]> Ambiguous => AmbiguousAnswers.Concat(AmbiguousCommands).Select(n => new object[] { n });

    [Theory]
    [MemberData(nameof(UnambiguousAnswers))]
    public async Task An_answer_is_recognised_without_response(string name)
    {
        // The first frame carries '@', unit and header; a continuation frame shows no direction.
        string frame = GoldenFrames.Frames(name)[0];

        JsonElement recognised = (await Cli.RunAsync("explain", frame, "--json")).Json();
        JsonElement told = (await Cli.RunAsync("explain", frame, "--response", "--json")).Json();

        recognised.GetProperty("direction").GetString().Should().Be("response", recognised.ToString());
        recognised.GetProperty("directionFrom").GetString().Should().Be("shape");
        told.GetProperty("directionFrom").GetString().Should().Be("option");
        foreach (string property in new[] { "valid", "endCode", "endCodeMeaning", "fields", "problems", "data" })
        {
            recognised.GetProperty(property).GetRawText().Should().Be(told.GetProperty(property).GetRawText(), "'{0}' is the same as with --response", property);
        }
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public async Task A_command_is_never_taken_for_an_answer(string name)
    {
        foreach (string frame in GoldenFrames.Frames(name))
        {
            JsonElement j = (await Cli.RunAsync("explain", frame, "--json")).Json();

            j.GetProperty("direction").GetString().Should().Be("command", j.ToString());
        }
    }

    [Theory]
    [MemberData(nameof(Ambiguous))]
    public async Task An_ambiguous_frame_is_explained_as_a_command_and_says_so(string name)
    {
        string frame = GoldenFrames.Frames(name)[0];

        CliResult r = await Cli.RunAsync("explain", frame, "--json");
        CliResult human = await Cli.RunAsync("explain", frame);

        r.ExitCode.Should().Be(0, r.ToString());
        JsonElement j = r.Json();
        j.GetProperty("direction").GetString().Should().Be("command");
        j.GetProperty("directionFrom").GetString().Should().Be("ambiguous");
        j.GetProperty("notes").EnumerateArray().Select(n => n.GetString()).Should().Contain(n => n!.Contains("ambiguous", StringComparison.OrdinalIgnoreCase) && n.Contains("--response"));
        human.Out.Should().Contain("ambiguous").And.Contain("--response");
    }

    [Fact]
    public async Task The_sc_answer_with_00_is_normal_completion_when_told_it_is_an_answer()
    {
        string frame = GoldenFrames.Frames("roof_sc_resp_ok")[0];

        JsonElement asCommand = (await Cli.RunAsync("explain", frame, "--json")).Json();
        JsonElement asAnswer = (await Cli.RunAsync("explain", frame, "--response", "--json")).Json();

        asCommand.GetProperty("fields").GetProperty("mode").GetString().Should().Be("PROGRAM");
        asAnswer.GetProperty("endCode").GetString().Should().Be("00");
    }

    [Fact]
    public async Task A_frame_that_fits_neither_direction_is_read_as_a_command_with_a_pointer_to_response()
    {
        string frame = GoldenFrames.Frames(Misencoded)[0];

        JsonElement j = (await Cli.RunAsync("explain", frame, "--json")).Json();

        j.GetProperty("direction").GetString().Should().Be("command");
        j.GetProperty("directionFrom").GetString().Should().Be("default");
        j.GetProperty("notes").EnumerateArray().Select(n => n.GetString()).Should().Contain(n => n!.Contains("--response"));
    }

    [Fact]
    public async Task A_recognised_answer_says_what_a_plc_would_make_of_it_as_a_command()
    {
        string frame = GoldenFrames.Frames("roof_wd_resp_ok")[0];

        CliResult r = await Cli.RunAsync("explain", frame);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("response (PLC to host)").And.Contain("end code 14").And.Contain("--command");
    }

    [Fact]
    public async Task Command_option_reads_an_answer_shaped_frame_as_a_command()
    {
        string frame = GoldenFrames.Frames("roof_wd_resp_ok")[0];

        JsonElement j = (await Cli.RunAsync("explain", frame, "--command", "--json")).Json();

        j.GetProperty("direction").GetString().Should().Be("command");
        j.GetProperty("directionFrom").GetString().Should().Be("option");
        j.GetProperty("fields").GetProperty("wouldAnswer").GetString().Should().Be("14");
    }

    [Fact]
    public async Task Response_and_command_together_are_a_usage_error()
    {
        CliResult r = await Cli.RunAsync("explain", GoldenFrames.Frames("roof_wd_resp_ok")[0], "--response", "--command");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--response").And.Contain("--command");
        r.Out.Should().BeEmpty();
    }

    [Fact]
    public async Task A_continuation_frame_says_its_direction_cannot_be_told()
    {
        string frame = GoldenFrames.Frames("c_rd_multi_response_40w")[1];

        JsonElement j = (await Cli.RunAsync("explain", frame, "--json")).Json();

        j.GetProperty("directionFrom").GetString().Should().Be("default");
        j.GetProperty("notes").EnumerateArray().Select(n => n.GetString()).Should().Contain(n => n!.Contains("--response"));
    }

    [Fact]
    public async Task A_ts_frame_ending_with_a_bare_cr_is_neither_a_command_nor_an_echo()
    {
        // TS is never divided, either way: a TS frame ending with CR and no '*' fits neither direction.
        string frame = CliExplainTests.Framed("@00TSABC").TrimEnd('*') + "\\r";

        JsonElement j = (await Cli.RunAsync("explain", frame, "--json")).Json();

        j.GetProperty("final").GetBoolean().Should().BeFalse();
        j.GetProperty("direction").GetString().Should().Be("command");
        j.GetProperty("directionFrom").GetString().Should().Be("default");
    }
}
