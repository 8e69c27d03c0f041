using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>explain</c> decodes FINS command parameters (and self-describing answer data), as the vectors' meanings state them.</summary>
public sealed class CliExplainFinsTests
{
    private static async Task<JsonElement> FieldsAsync(string vector, params string[] options)
    {
        CliResult r = await Cli.RunAsync(["explain", GoldenFrames.Frames(vector)[0], "--json", .. options]);
        r.ExitCode.Should().Be(0, r.ToString());
        return r.Json().GetProperty("fields");
    }

    private static string[] Addresses(JsonElement items) => items.EnumerateArray().Select(i => i.GetProperty("address").GetString()!).ToArray();

    [Fact]
    public async Task Memory_area_read_gives_area_address_and_count()
    {
        // FINS 0101 read D100, 2 words (area 82, addr 0064 hex, bit 00, count 0002)
        JsonElement f = await FieldsAsync("f_0101_cmd");

        f.GetProperty("areaCode").GetString().Should().Be("82");
        f.GetProperty("area").GetString().Should().Be("DM word");
        f.GetProperty("address").GetString().Should().Be("D100");
        f.GetProperty("word").GetInt32().Should().Be(100);
        f.GetProperty("bit").GetInt32().Should().Be(0);
        f.GetProperty("count").GetInt32().Should().Be(2);
    }

    [Fact]
    public async Task Memory_area_read_of_bits_names_the_first_bit()
    {
        // FINS 0101: area 30 (CIO bit), CIO 0000.00, 5 bits
        JsonElement f = await FieldsAsync("java_fins_read_cio_bits");

        f.GetProperty("areaCode").GetString().Should().Be("30");
        f.GetProperty("address").GetString().Should().Be("CIO0.00");
        f.GetProperty("count").GetInt32().Should().Be(5);
    }

    [Fact]
    public async Task Memory_area_read_behind_a_network_header()
    {
        // ... SID 01, then 0101 read D0 x1
        JsonElement f = await FieldsAsync("f_network_cmd");

        f.GetProperty("dna").GetString().Should().Be("01");
        f.GetProperty("address").GetString().Should().Be("D0");
        f.GetProperty("count").GetInt32().Should().Be(1);
    }

    [Fact]
    public async Task Memory_area_write_gives_the_words()
    {
        // FINS 0102 write W10 = BEEF (area B1)
        JsonElement f = await FieldsAsync("f_0102_cmd");

        f.GetProperty("areaCode").GetString().Should().Be("B1");
        f.GetProperty("address").GetString().Should().Be("W10");
        f.GetProperty("count").GetInt32().Should().Be(1);
        f.GetProperty("words").EnumerateArray().Select(w => w.GetInt32()).Should().Equal(0xBEEF);
    }

    [Fact]
    public async Task Memory_area_fill_gives_range_and_value()
    {
        // FINS 0103 MEMORY AREA FILL D1000..D1009 with 0000
        JsonElement f = await FieldsAsync("f_0103_cmd");

        f.GetProperty("address").GetString().Should().Be("D1000");
        f.GetProperty("count").GetInt32().Should().Be(10);
        f.GetProperty("value").GetInt32().Should().Be(0);
    }

    [Fact]
    public async Task Multiple_memory_area_read_lists_each_item()
    {
        // FINS 0104 multiple read: D0 word, CIO1 word, CIO 1.05 bit
        JsonElement f = await FieldsAsync("f_0104_cmd");

        Addresses(f.GetProperty("items")).Should().Equal("D0", "CIO1", "CIO1.05");
        f.GetProperty("items")[2].GetProperty("areaCode").GetString().Should().Be("30");
    }

    [Fact]
    public async Task Memory_area_transfer_gives_source_destination_and_count()
    {
        // FINS 0105 transfer D0..D15 -> D100..D115
        JsonElement f = await FieldsAsync("f_0105_cmd");

        f.GetProperty("source").GetProperty("address").GetString().Should().Be("D0");
        f.GetProperty("destination").GetProperty("address").GetString().Should().Be("D100");
        f.GetProperty("count").GetInt32().Should().Be(16);
    }

    [Fact]
    public async Task Run_and_stop_give_program_number_and_mode()
    {
        // FINS 0401 RUN: program no FFFF, mode 02 = MONITOR; FINS 0402 STOP, program no FFFF
        JsonElement run = await FieldsAsync("f_0401_run_monitor");
        JsonElement stop = await FieldsAsync("f_0402_stop");

        run.GetProperty("programNumber").GetString().Should().Be("FFFF");
        run.GetProperty("mode").GetString().Should().Be("MONITOR");
        stop.GetProperty("programNumber").GetString().Should().Be("FFFF");
    }

    [Fact]
    public async Task Cpu_unit_data_read_and_cycle_time_read_give_their_one_byte()
    {
        // FINS 0501 (parameter 00); FINS 0620, parameter 01 = read
        JsonElement data = await FieldsAsync("f_0501_cmd");
        JsonElement cycle = await FieldsAsync("f_0620_cmd");

        data.GetProperty("selector").GetString().Should().Be("00");
        cycle.GetProperty("initialize").GetBoolean().Should().BeFalse();
    }

    [Fact]
    public async Task Clock_write_gives_the_time()
    {
        // FINS 0702 CLOCK WRITE 24 05 17 13 45 30 05: 2024-05-17 13:45:30, day of week 05 (Friday)
        JsonElement f = await FieldsAsync("f_0702_cmd");

        f.GetProperty("clock").GetString().Should().Be("2024-05-17 13:45:30");
        f.GetProperty("dayOfWeek").GetString().Should().Be("Friday");
    }

    [Fact]
    public async Task Error_clear_and_error_log_read_give_their_parameters()
    {
        // FINS 2101 ERROR CLEAR, error code FFFF; FINS 2102 ERROR LOG READ: from record 0, 5 records
        JsonElement clear = await FieldsAsync("f_2101_cmd");
        JsonElement log = await FieldsAsync("f_2102_cmd");

        clear.GetProperty("errorCode").GetString().Should().Be("FFFF");
        log.GetProperty("firstRecord").GetInt32().Should().Be(0);
        log.GetProperty("count").GetInt32().Should().Be(5);
    }

    [Fact]
    public async Task Forced_set_reset_lists_action_and_bit()
    {
        // FINS 2301 FORCED SET/RESET: 1 bit, spec 0001 (forced set), area 30, CIO 0001.00
        JsonElement f = await FieldsAsync("f_2301_cmd");

        JsonElement item = f.GetProperty("items").EnumerateArray().Should().ContainSingle().Subject;
        item.GetProperty("action").GetString().Should().Be("ForceSet");
        item.GetProperty("address").GetString().Should().Be("CIO1.00");
    }

    [Fact]
    public async Task Parameters_in_text_name_the_address()
    {
        CliResult r = await Cli.RunAsync("explain", GoldenFrames.Frames("f_0104_cmd")[0]);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("CIO1.05").And.Contain("D0");
    }

    [Fact]
    public async Task Parameters_a_plc_refuses_give_the_fins_response_code_it_would_answer()
    {
        // 0101 with its count cut off: 82 0064 00 and no count - too short (1002), written by hand with its FCS.
        JsonElement j = (await Cli.RunAsync("explain", CliExplainTests.Framed("@00FA000000000010182006400"), "--json")).Json();

        j.GetProperty("fields").GetProperty("wouldAnswer").GetString().Should().Be("1002");
    }

    [Fact]
    public async Task Cpu_unit_status_answer_is_decoded()
    {
        // FINS 0601 response: status 01 (running), mode 02 (MONITOR), fatal 0000, non-fatal 0000, ...
        JsonElement f = await FieldsAsync("f_0601_rsp", "--response");

        f.GetProperty("running").GetBoolean().Should().BeTrue();
        f.GetProperty("mode").GetString().Should().Be("MONITOR");
        f.GetProperty("fatalErrors").GetInt32().Should().Be(0);
    }

    [Fact]
    public async Task Clock_read_answer_is_decoded()
    {
        // FINS 0701 response: 2024-05-17 13:45:30, day-of-week 05 (Fri)
        JsonElement f = await FieldsAsync("f_0701_rsp", "--response");

        f.GetProperty("clock").GetString().Should().Be("2024-05-17 13:45:30");
        f.GetProperty("dayOfWeek").GetString().Should().Be("Friday");
    }
}
