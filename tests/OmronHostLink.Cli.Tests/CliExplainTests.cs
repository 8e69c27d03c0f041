using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>explain</c> against the golden vectors: every published and constructed frame.</summary>
public sealed class CliExplainTests
{
    private static readonly Lazy<JsonElement[]> Vectors = new(() =>
    {
        using JsonDocument doc = JsonDocument.Parse(File.ReadAllText(GoldenVectors.FilePath));
        return doc.RootElement.EnumerateArray().Select(v => v.Clone()).ToArray();
    });

    public static TheoryData<string> VectorNames()
    {
        var data = new TheoryData<string>();
        foreach (JsonElement v in Vectors.Value)
        {
            data.Add(v.GetProperty("name").GetString()!);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(VectorNames))]
    public async Task Explain_agrees_with_each_vector_on_the_fcs(string name)
    {
        JsonElement vector = Vectors.Value.Single(v => v.GetProperty("name").GetString() == name);
        bool response = vector.GetProperty("direction").GetString() == "response";
        bool fcsOk = vector.GetProperty("fcs_ok").GetBoolean();
        string[] frames = GoldenFrames.Frames(name);

        var results = new List<(CliResult Result, JsonElement Json)>();
        foreach (string frame in frames)
        {
            CliResult r = response
                ? await Cli.RunAsync("explain", frame, "--response", "--json")
                : await Cli.RunAsync("explain", frame, "--json");
            results.Add((r, r.Json()));
        }

        foreach ((CliResult r, JsonElement j) in results)
        {
            r.ExitCode.Should().Be(j.GetProperty("valid").GetBoolean() ? 0 : 2, r.ToString());
            if (j.GetProperty("fcs").ValueKind == JsonValueKind.Object)
            {
                // The FCS the frame carries is the two characters before the ending, as the vector spells it.
                string frameText = j.GetProperty("frame").GetString()!.Replace("\\r", string.Empty, StringComparison.Ordinal).TrimEnd('*');
                j.GetProperty("fcs").GetProperty("found").GetString().Should().Be(frameText[^2..]);
            }
        }

        bool allFcsOk = results.All(x => x.Json.GetProperty("fcs").ValueKind != JsonValueKind.Object || x.Json.GetProperty("fcs").GetProperty("ok").GetBoolean());
        allFcsOk.Should().Be(fcsOk, "the vector says fcs_ok = {0}", fcsOk);
        if (fcsOk)
        {
            results.Should().OnlyContain(x => x.Result.ExitCode == 0, "a frame with a good FCS and a known shape is valid: {0}", string.Join("\n", results.Select(x => x.Result.ToString())));
        }
        else
        {
            results.Should().Contain(x => x.Result.ExitCode == 2);
        }
    }

    [Fact]
    public async Task Explain_a_command_decodes_its_fields()
    {
        string frame = GoldenFrames.Frames("dws_rd_dm_read")[0];

        CliResult r = await Cli.RunAsync("explain", frame, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        JsonElement j = r.Json();
        j.GetProperty("valid").GetBoolean().Should().BeTrue();
        j.GetProperty("unit").GetInt32().Should().Be(0);
        j.GetProperty("header").GetString().Should().Be("RD");
        j.GetProperty("endCode").ValueKind.Should().Be(JsonValueKind.Null);
        JsonElement fcs = j.GetProperty("fcs");
        fcs.GetProperty("ok").GetBoolean().Should().BeTrue();
        fcs.GetProperty("expected").GetString().Should().Be(fcs.GetProperty("found").GetString());
        JsonElement fields = j.GetProperty("fields");
        fields.GetProperty("area").GetString().Should().Be("DM");
        fields.GetProperty("begin").GetInt32().Should().Be(0);
        fields.GetProperty("count").GetInt32().Should().Be(10);
    }

    [Fact]
    public async Task Explain_a_response_gives_end_code_and_meaning()
    {
        string frame = GoldenFrames.Frames("c_wd_resp_01")[0];

        JsonElement j = (await Cli.RunAsync("explain", frame, "--response", "--json")).Json();

        j.GetProperty("endCode").GetString().Should().Be("01");
        j.GetProperty("endCodeMeaning").GetString().Should().Contain("RUN mode");
    }

    [Fact]
    public async Task Explain_a_read_response_decodes_the_words()
    {
        string frame = GoldenFrames.Frames("c_rd_resp_3w")[0];

        JsonElement j = (await Cli.RunAsync("explain", frame, "--response", "--json")).Json();

        j.GetProperty("endCode").GetString().Should().Be("00");
        j.GetProperty("fields").GetProperty("words").EnumerateArray().Select(w => w.GetInt32()).Should().Equal(0x000A, 0xFFFF, 0x8000);
    }

    [Fact]
    public async Task Explain_takes_the_frame_with_a_literal_backslash_r_or_without_an_ending()
    {
        string frame = GoldenFrames.Frames("c_mm_resp_csj")[0];
        string literal = frame.Replace("\r", "\\r", StringComparison.Ordinal);
        string bare = frame.TrimEnd('\r').TrimEnd('*');

        JsonElement a = (await Cli.RunAsync("explain", literal, "--response", "--json")).Json();
        JsonElement b = (await Cli.RunAsync("explain", bare, "--response", "--json")).Json();

        foreach (JsonElement j in new[] { a, b })
        {
            j.GetProperty("valid").GetBoolean().Should().BeTrue();
            j.GetProperty("fields").GetProperty("model").GetString().Should().Be("CS/CJ");
        }
    }

    [Fact]
    public async Task Explain_a_damaged_frame_reports_expected_and_found_and_exits_2()
    {
        string frame = GoldenFrames.Frames("manual_fcs_example_RR")[0];

        CliResult r = await Cli.RunAsync("explain", frame);

        r.ExitCode.Should().Be(2, r.ToString());
        r.Out.Should().Contain("MISMATCH");
        r.Err.Should().Contain("FCS");
    }

    [Fact]
    public async Task Explain_a_fins_response_decodes_the_response_code()
    {
        string frame = GoldenFrames.Frames("f_rsp_1103")[0];

        JsonElement j = (await Cli.RunAsync("explain", frame, "--response", "--json")).Json();

        j.GetProperty("valid").GetBoolean().Should().BeTrue();
        j.GetProperty("fields").GetProperty("responseCode").GetString().Should().Be("1103");
        j.GetProperty("fields").GetProperty("command").GetString().Should().Be("0101");
    }

    [Fact]
    public async Task Explain_calls_an_fcs_that_differs_only_in_case_a_lowercase_fcs()
    {
        string frame = GoldenFrames.Frames("c_ic_resp")[0]; // @00IC4A*
        string lower = frame.Replace("4A*", "4a*", StringComparison.Ordinal);

        CliResult human = await Cli.RunAsync("explain", lower, "--response");
        CliResult json = await Cli.RunAsync("explain", lower, "--response", "--json");

        human.ExitCode.Should().Be(2, "the link refuses a lowercase FCS as it refuses any changed character: {0}", human);
        human.Out.Should().Contain("lowercase FCS").And.NotContain("MISMATCH");
        human.Err.Should().Contain("lowercase FCS").And.Contain("4a").And.NotContain("FCS error");
        JsonElement fcs = json.Json().GetProperty("fcs");
        fcs.GetProperty("ok").GetBoolean().Should().BeFalse();
        fcs.GetProperty("lowercase").GetBoolean().Should().BeTrue();
    }

    [Fact]
    public async Task Explain_still_calls_a_wrong_lowercase_fcs_wrong()
    {
        string frame = GoldenFrames.Frames("c_ic_resp")[0].Replace("4A*", "4b*", StringComparison.Ordinal);

        CliResult r = await Cli.RunAsync("explain", frame, "--response");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Out.Should().Contain("MISMATCH").And.NotContain("lowercase");
    }

    [Fact]
    public async Task Explain_reports_a_frame_over_131_characters_as_end_code_18()
    {
        // 30 words of WD: 9 + 120 + FCS + '*' + CR = 133 characters; a CS/CJ answers 18 (frame length error).
        string frame = Framed("@00WD0000" + string.Concat(Enumerable.Repeat("1234", 30)));

        CliResult r = await Cli.RunAsync("explain", frame, "--json");

        r.ExitCode.Should().Be(2, r.ToString());
        JsonElement j = r.Json();
        j.GetProperty("fields").GetProperty("wouldAnswer").GetString().Should().Be("18");
        string problem = j.GetProperty("problems")[0].GetString()!;
        problem.Should().Contain("133").And.Contain("131").And.Contain("end code 18").And.Contain("frame length error");
        r.Err.Should().Contain("end code 18");
    }

    [Fact]
    public async Task Explain_takes_a_frame_of_exactly_131_characters()
    {
        // 29 words of WD: 9 + 116 + FCS + '*' + CR = 131 characters.
        string frame = Framed("@00WD0000" + string.Concat(Enumerable.Repeat("1234", 29)));

        CliResult r = await Cli.RunAsync("explain", frame, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("problems").GetArrayLength().Should().Be(0);
    }

    [Fact]
    public async Task Explain_reports_an_answer_over_131_characters_as_one_no_plc_sends()
    {
        // An RD answer of 31 words in one frame: 7 + 124 + FCS + '*' + CR = 135 characters.
        string frame = Framed("@00RD00" + string.Concat(Enumerable.Repeat("ABCD", 31)));

        JsonElement j = (await Cli.RunAsync("explain", frame, "--response", "--json")).Json();

        j.GetProperty("valid").GetBoolean().Should().BeFalse();
        j.GetProperty("problems")[0].GetString().Should().Contain("135").And.Contain("131");
    }

    [Fact]
    public async Task Explain_reports_a_later_frame_over_128_characters_as_end_code_A8()
    {
        // A continuation frame of 32 words: 128 + FCS + '*' + CR = 132 characters; a later frame holds at most 128.
        string frame = Framed(string.Concat(Enumerable.Repeat("0F0F", 32)));

        JsonElement j = (await Cli.RunAsync("explain", frame, "--json")).Json();

        j.GetProperty("fields").GetProperty("wouldAnswer").GetString().Should().Be("A8");
        j.GetProperty("problems")[0].GetString().Should().Contain("128").And.Contain("A8");
    }

    /// <summary>The text with its FCS (XOR of every character, two upper-case hex digits) and <c>*</c>.</summary>
    internal static string Framed(string text)
    {
        int fcs = 0;
        foreach (char c in text)
        {
            fcs ^= c;
        }

        return $"{text}{fcs:X2}*";
    }

    [Fact]
    public async Task Explain_holds_fa_frames_to_their_own_limit_not_131()
    {
        // FINS 0102 writing 60 words to D0: an FA frame of 274 characters, within the 1,115 an FA frame may hold.
        string frame = Framed("@00FA000000000010282000000003C" + string.Concat(Enumerable.Repeat("1234", 60)));

        CliResult r = await Cli.RunAsync("explain", frame, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("fields").GetProperty("count").GetInt32().Should().Be(60);
    }
}
