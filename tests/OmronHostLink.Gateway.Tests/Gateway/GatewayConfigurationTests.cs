using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Gateway.Tests.Telemetry;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>No configuration mistake is silently ignored: every bad value fails the start, naming its key.</summary>
public sealed class GatewayConfigurationTests
{
    public static TheoryData<string, string, string> BadValues => new()
    {
        { "HostLink:Links:plc:Groups:g:Interval", "abc", "HostLink:Links:plc:Groups:g:Interval 'abc'" },
        { "HostLink:Links:plc:Groups:g:Interval", "5", "HostLink:Links:plc:Groups:g:Interval '5'" },
        { "HostLink:Links:plc:Groups:g:Interval", "500 parsecs", "HostLink:Links:plc:Groups:g:Interval '500 parsecs' is not a duration" },
        { "HostLink:Links:plc:Groups:g:Count", "abc", "HostLink:Links:plc:Groups:g:Count 'abc'" },
        { "HostLink:Links:plc:Groups:g:Unit", "one", "HostLink:Links:plc:Groups:g:Unit 'one'" },
        { "HostLink:Links:plc:CommandSet", "Finz", "HostLink:Links:plc:CommandSet: 'Finz'" },
        { "HostLink:Links:plc:CommandSet", "7", "HostLink:Links:plc:CommandSet: '7'" },
        { "HostLink:Links:plc:WordOrder", "Big", "HostLink:Links:plc:WordOrder: 'Big'" },
        { "HostLink:Links:plc:Enabled", "yes", "HostLink:Links:plc:Enabled 'yes'" },
        { "HostLink:Links:plc:TurnaroundAllowance", "300", "HostLink:Links:plc:TurnaroundAllowance: '300'" },
        { "HostLink:Links:plc:Backoff:Max", "later", "HostLink:Links:plc:Backoff:Max 'later'" },
        { "HostLink:Links:plc:Groups:g:Intervall", "00:00:01", "HostLink:Links:plc:Groups:g:Intervall is not a setting" },
        { "HostLink:Links:plc:Tcpp", "127.0.0.1:9", "HostLink:Links:plc:Tcpp: not a Host Link client setting" },
        { "Simulator:Turnaround", "abc", "Simulator:Turnaround 'abc'" },
        { "Simulator:Port", "http", "Simulator:Port 'http'" },
    };

    [Theory]
    [MemberData(nameof(BadValues))]
    public async Task A_bad_value_fails_the_start_naming_its_key(string key, string value, string expected)
    {
        var config = new Dictionary<string, string?>
        {
            ["HostLink:Links:plc:Tcp"] = "127.0.0.1:9",
            ["HostLink:Links:plc:Groups:g:Address"] = "D0",
            ["HostLink:Links:plc:Groups:h:Address"] = "D1",
            [key] = value,
        };
        var logs = new CapturingLoggerProvider();
        using IHost host = Build(config, logs);

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        error.Should().BeOfType<OptionsValidationException>("a configuration mistake is a validation failure, not a crash: {0}", error);
        ((OptionsValidationException)error!).Failures.Should().Contain(f => f.Contains(expected, StringComparison.Ordinal), "the failure names the key ({0})", string.Join(" | ", ((OptionsValidationException)error).Failures));
        logs.WithEvent(GatewayLog.Events.LinkStarted).Should().BeEmpty("nothing is polled with a bad configuration");
    }

    [Fact]
    public async Task The_failure_does_not_log_the_hosts_stack_trace()
    {
        var config = new Dictionary<string, string?>
        {
            ["HostLink:Links:plc:Tcp"] = "127.0.0.1:9",
            ["HostLink:Links:plc:Groups:g:Address"] = "D0",
            ["HostLink:Links:plc:Groups:g:Interval"] = "abc",
        };
        var logs = new CapturingLoggerProvider();
        using IHost host = Build(config, logs);

        await Record.ExceptionAsync(() => host.StartAsync());

        logs.Dump().Should().NotContain("Hosting failed to start");
    }

    [Fact]
    public async Task The_worker_process_prints_one_clear_message_and_exits_2()
    {
        await using GatewayProcess process = GatewayProcess.Start(
        [
            "--HostLink:Links:plc:Tcp=127.0.0.1:9",
            "--HostLink:Links:plc:Groups:g:Address=D0",
            "--HostLink:Links:plc:Groups:g:Interval=abc",
        ]);
        if (await process.WaitForExitAsync(TimeSpan.FromSeconds(20)) is null)
        {
            await process.KillAsync();
        }

        string output = process.Output;
        process.ExitCode.Should().Be(2, output);
        output.Should().Contain("HostLink:Links:plc:Groups:g:Interval 'abc'");
        output.Should().NotContain("Hosting failed to start").And.NotMatchRegex(@"(?m)^\s+at ", "no framework stack trace: {0}", output);
    }

    private static IHost Build(Dictionary<string, string?> config, CapturingLoggerProvider logs)
    {
        HostApplicationBuilder builder = TestGatewayHost.CreateBuilder(config);
        builder.Logging.AddProvider(logs);
        return builder.Build();
    }
}
