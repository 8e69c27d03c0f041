using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary>read, write and monitor against the simulator.</summary>
public sealed class CliReadWriteTests
{
    [Fact]
    public async Task Read_words_human_shows_address_hex_and_decimal()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D100", new ushort[] { 1234, 0xBEEF });

        CliResult r = await sim.RunAsync("read", "D100", "2");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Lines().Should().HaveCount(2);
        r.Lines()[0].Should().Contain("D100").And.Contain("0x04D2").And.Contain("1234");
        r.Lines()[1].Should().Contain("D101").And.Contain("0xBEEF").And.Contain("48879");
    }

    [Fact]
    public async Task Read_json_is_one_document_with_the_documented_fields()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D100", new ushort[] { 1, 0xFFFF, 3 });

        JsonElement j = (await sim.RunAsync("read", "D100", "3", "--json")).Json();

        j.GetProperty("address").GetString().Should().Be("D100");
        j.GetProperty("count").GetInt32().Should().Be(3);
        j.GetProperty("as").GetString().Should().Be("word");
        j.GetProperty("values").EnumerateArray().Select(v => v.GetInt32()).Should().Equal(1, 65535, 3);
    }

    [Fact]
    public async Task Read_of_many_words_spanning_frames_returns_them_all()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        ushort[] words = Enumerable.Range(0, 100).Select(i => (ushort)(i * 311)).ToArray();
        sim.Plc.WriteWords("D2000", words);

        JsonElement j = (await sim.RunAsync("read", "D2000", "100", "--json")).Json();

        j.GetProperty("values").EnumerateArray().Select(v => (ushort)v.GetInt32()).Should().Equal(words);
    }

    [Theory]
    [InlineData("int16", new ushort[] { 0xFFFE }, "[-2]")]
    [InlineData("uint16", new ushort[] { 0xFFFE }, "[65534]")]
    [InlineData("bcd", new ushort[] { 0x1234 }, "[1234]")]
    [InlineData("bcd", new ushort[] { 0x12AB }, "[null]")]
    [InlineData("int32", new ushort[] { 0xFFFF, 0xFFFF }, "[-1]")]
    [InlineData("uint32", new ushort[] { 0x0000, 0x0001 }, "[65536]")]
    [InlineData("float", new ushort[] { 0x0000, 0x3FC0 }, "[1.5]")]
    public async Task Read_as_a_type_gives_the_natural_json_value(string kind, ushort[] words, string expected)
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D10", words);

        JsonElement j = (await sim.RunAsync("read", "D10", "--as", kind, "--json")).Json();

        j.GetProperty("as").GetString().Should().Be(kind);
        j.GetProperty("values").GetRawText().Should().Be(expected);
    }

    [Fact]
    public async Task Read_string_reads_characters()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D300", PlcWords.FromString("PUMP 7"));

        JsonElement j = (await sim.RunAsync("read", "D300", "6", "--as", "string", "--json")).Json();

        j.GetProperty("values")[0].GetString().Should().Be("PUMP 7");
    }

    [Fact]
    public async Task Read_bits_from_a_bit_address_across_a_word_boundary()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.SetBit("CIO100.15", true);
        sim.Plc.SetBit("CIO101.01", true);

        CliResult r = await sim.RunAsync("read", "CIO 100.14", "4", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("as").GetString().Should().Be("bit");
        r.Json().GetProperty("values").EnumerateArray().Select(v => v.GetBoolean()).Should().Equal(false, true, false, true);
    }

    [Fact]
    public async Task Read_accepts_an_address_typed_as_two_words()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.SetBit("CIO100.05", true);

        CliResult r = await sim.RunAsync("read", "CIO", "100.05");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("CIO100.05").And.Contain("ON");
    }

    [Fact]
    public async Task Read_timer_completion_flag_and_present_value()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.SetFlag(PlcArea.Timer, 5, true);
        sim.Plc.WriteWord(PlcArea.Timer, 5, 0x0042);

        JsonElement flag = (await sim.RunAsync("read", "T5", "--as", "bit", "--json")).Json();
        JsonElement pv = (await sim.RunAsync("read", "T5", "--json")).Json();

        flag.GetProperty("values")[0].GetBoolean().Should().BeTrue();
        pv.GetProperty("values")[0].GetInt32().Should().Be(0x42);
    }

    [Fact]
    public async Task Write_in_program_mode_changes_memory()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Program);

        CliResult r = await sim.RunAsync("write", "D100", "1", "0x10", "65535");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("D100").And.Contain("D102");
        sim.Plc.ReadWords("D100", 3).Should().Equal(1, 0x10, 0xFFFF);
    }

    [Theory]
    [InlineData("int16", "-2", new ushort[] { 0xFFFE })]
    [InlineData("bcd", "1234", new ushort[] { 0x1234 })]
    [InlineData("int32", "-1", new ushort[] { 0xFFFF, 0xFFFF })]
    [InlineData("uint32", "65536", new ushort[] { 0x0000, 0x0001 })]
    [InlineData("float", "1.5", new ushort[] { 0x0000, 0x3FC0 })]
    [InlineData("string", "AB", new ushort[] { 0x4142 })]
    public async Task Write_as_a_type_stores_the_words(string kind, string value, ushort[] expected)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("write", "D50", value, "--as", kind, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("ok").GetBoolean().Should().BeTrue();
        sim.Plc.ReadWords("D50", expected.Length).Should().Equal(expected);
    }

    [Fact]
    public async Task Write_bit_with_read_modify_write()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWord(PlcArea.Dm, 7, 0x0001);

        CliResult r = await sim.RunAsync("write", "D7.04", "on", "--read-modify-write");

        r.ExitCode.Should().Be(0, r.ToString());
        sim.Plc.ReadWord(PlcArea.Dm, 7).Should().Be(0x0011);
    }

    [Fact]
    public async Task Write_in_run_mode_exits_3_naming_end_code_01()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult r = await sim.RunAsync("write", "D100", "5");

        r.ExitCode.Should().Be(3, r.ToString());
        r.Err.Should().Contain("01").And.Contain("Not executable in RUN mode");
        r.Err.Trim().Split('\n').Should().HaveCount(1, "an error is one sentence without a stack trace");
        sim.Plc.ReadWord(PlcArea.Dm, 100).Should().Be(0);
    }

    [Fact]
    public async Task Monitor_prints_one_json_line_per_poll_with_a_change()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D0", new ushort[] { 7, 8 });

        CliResult r = await sim.RunAsync("monitor", "D0", "2", "--interval", "20ms", "--count", "3", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        string[] lines = r.Lines();
        lines.Should().HaveCount(1, "nothing changed after the first poll");
        JsonElement j = JsonDocument.Parse(lines[0]).RootElement;
        j.GetProperty("values").EnumerateArray().Select(v => v.GetInt32()).Should().Equal(7, 8);
        j.GetProperty("changed").EnumerateArray().Select(v => v.GetString()).Should().Equal("D0", "D1");
    }

    [Fact]
    public async Task Monitor_prints_changes_and_stops_cleanly_on_cancellation()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        using var cts = new CancellationTokenSource();
        var stdout = new StringWriter();
        TextWriter output = TextWriter.Synchronized(stdout);
        Task<int> run = OmronHostLink.Cli.CliApp.RunAsync(Cli.WithAllowance(["monitor", "D0", "2", "--interval", "30ms", "--json", "--tcp", sim.Endpoint]), output, TextWriter.Null, cts.Token);
        string[] Lines() { lock (output) { return stdout.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries); } }

        // The change is made once the first poll is printed, and the monitor is stopped once it has printed the change.
        await UntilAsync(() => Lines().Length >= 1 || run.IsCompleted);
        sim.Plc.WriteWord(PlcArea.Dm, 1, 99);
        await UntilAsync(() => Lines().Length >= 2 || run.IsCompleted);
        cts.Cancel();

        int exit = await run.WaitAsync(TimeSpan.FromSeconds(10));

        exit.Should().Be(0, string.Join('\n', Lines()));
        string[] lines = Lines();
        lines.Should().HaveCountGreaterThanOrEqualTo(2);
        JsonElement change = JsonDocument.Parse(lines[1]).RootElement;
        change.GetProperty("changed").EnumerateArray().Select(v => v.GetString()).Should().Equal("D1");
        change.GetProperty("values")[1].GetInt32().Should().Be(99);
    }

    private static Task UntilAsync(Func<bool> condition) => Eventually.UntilAsync(condition);
}
