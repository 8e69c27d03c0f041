using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary>With --json, every outcome is one JSON document on stdout: results and failures alike.</summary>
public sealed class CliJsonTests
{
    [Fact]
    public async Task An_end_code_is_a_json_error_with_the_same_exit_code()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult r = await sim.RunAsync("write", "D100", "5", "--json");

        r.ExitCode.Should().Be(3, r.ToString());
        JsonElement error = r.Json().GetProperty("error");
        error.GetProperty("kind").GetString().Should().Be("endCode");
        error.GetProperty("endCode").GetString().Should().Be("01");
        error.GetProperty("message").GetString().Should().Contain("Not executable in RUN mode");
    }

    [Fact]
    public void A_fins_end_code_carries_its_four_digits()
    {
        var e = new FinsEndCodeException(new OmronHostLink.Protocol.Fins.FinsEndCode(0x2206), 0x0102, 0);

        OmronHostLink.Cli.ErrorInfo error = OmronHostLink.Cli.CliContext.ErrorOf(e);

        error.Kind.Should().Be("endCode");
        error.EndCode.Should().Be("2206");
    }

    [Fact]
    public async Task A_timeout_is_a_json_error_with_exit_4()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("read", "D0", "--unit", "5", "--timeout", "50ms", "--retries", "0", "--json");

        r.ExitCode.Should().Be(4, r.ToString());
        JsonElement error = r.Json().GetProperty("error");
        error.GetProperty("kind").GetString().Should().Be("timeout");
        error.GetProperty("endCode").ValueKind.Should().Be(JsonValueKind.Null);
        error.GetProperty("message").GetString().Should().NotBeNullOrWhiteSpace();
    }

    [Fact]
    public async Task A_refused_connection_is_a_json_error_with_exit_4()
    {
        CliResult r = await Cli.RunAsync("status", "--tcp", $"127.0.0.1:{Cli.ClosedPort()}", "--json");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Json().GetProperty("error").GetProperty("kind").GetString().Should().Be("connection");
    }

    [Theory]
    [InlineData("read", "D99999", "--json", "--tcp", "127.0.0.1:1")]
    [InlineData("read", "D1", "--as", "quad", "--json", "--tcp", "127.0.0.1:1")]
    [InlineData("status", "--json")]
    public async Task Invalid_input_is_a_json_usage_error_with_exit_2(params string[] args)
    {
        CliResult r = await Cli.RunAsync(args);

        r.ExitCode.Should().Be(2, r.ToString());
        JsonElement error = r.Json().GetProperty("error");
        error.GetProperty("kind").GetString().Should().Be("usage");
        error.GetProperty("message").GetString().Should().NotBeNullOrWhiteSpace();
    }

    [Fact]
    public async Task Read_json_carries_the_unit_and_a_timestamp()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0, 3]);
        DateTimeOffset before = DateTimeOffset.Now.AddSeconds(-1);

        JsonElement j = (await sim.RunAsync("read", "D0", "--unit", "3", "--json")).Json();

        j.GetProperty("unit").GetInt32().Should().Be(3);
        j.GetProperty("time").GetDateTimeOffset().Should().BeOnOrAfter(before).And.BeOnOrBefore(DateTimeOffset.Now.AddSeconds(1));
    }

    [Theory]
    [InlineData("word", new[] { "1", "0x10" }, "[1,16]", "[1,16]")]
    [InlineData("float", new[] { "1.5" }, "[1.5]", "[0,16320]")]
    [InlineData("int16", new[] { "-2" }, "[-2]", "[65534]")]
    public async Task Write_json_carries_what_was_written(string kind, string[] values, string expectedValues, string expectedWords)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync(["write", "D50", .. values, "--as", kind, "--json"]);

        r.ExitCode.Should().Be(0, r.ToString());
        JsonElement j = r.Json();
        j.GetProperty("unit").GetInt32().Should().Be(0);
        j.GetProperty("address").GetString().Should().Be("D50");
        j.GetProperty("values").GetRawText().Should().Be(expectedValues);
        j.GetProperty("words").GetRawText().Should().Be(expectedWords);
        j.GetProperty("ok").GetBoolean().Should().BeTrue();
    }

    [Fact]
    public async Task Write_json_of_a_string_carries_the_text()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        JsonElement j = (await sim.RunAsync("write", "D50", "PUMP 7", "--as", "string", "--json")).Json();

        j.GetProperty("values")[0].GetString().Should().Be("PUMP 7");
    }

    [Fact]
    public async Task Write_json_of_bits_carries_the_bits()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        JsonElement j = (await sim.RunAsync("write", "CIO10.02", "1", "0", "1", "--fins", "--json")).Json();

        j.GetProperty("values").GetRawText().Should().Be("[true,false,true]");
    }

    [Theory]
    [InlineData("ZZ", "IC")]
    [InlineData("RD000A0001", "15")]
    public async Task A_raw_end_code_is_one_document_with_the_frames_and_the_error(string text, string endCode)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("raw", text, "--json");

        r.ExitCode.Should().Be(3, r.ToString());
        JsonElement j = r.Json();
        j.GetProperty("received").GetArrayLength().Should().Be(1);
        j.GetProperty("error").GetProperty("kind").GetString().Should().Be("endCode");
        j.GetProperty("error").GetProperty("endCode").GetString().Should().Be(endCode);
    }
}
