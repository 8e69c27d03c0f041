using System.Net;
using System.Net.Sockets;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Status;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Gateway.Tests.Telemetry;
using OmronHostLink.Simulator;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// The <c>Status</c> section: its defaults, every mistake refused at start with one message naming its key (a bind
/// beyond this machine without a token among them), a port in use stopping the gateway with one line, and nothing at
/// all when the section is off.
/// </summary>
public sealed class StatusConfigurationTests
{
    public static TheoryData<string, string> Mistakes() => new()
    {
        // the command line, what the message says
        { "--Status:Address=0.0.0.0", "Status:AccessToken is required when Status:Address is 0.0.0.0 (not a loopback address): anyone who reaches port 9680 could read the page." },
        { "--Status:Address=:: --Status:Port=8080", "Status:AccessToken is required when Status:Address is :: (not a loopback address): anyone who reaches port 8080 could read the page." },
        { "--Status:Address=192.0.2.7", "Status:AccessToken is required when Status:Address is 192.0.2.7" },
        { "--Status:Address=plant-gw.local", "Status:Address 'plant-gw.local' is not an IP address" },
        { "--Status:Address=http://127.0.0.1", "Status:Address 'http://127.0.0.1' is not an IP address" },
        { "--Status:Port=0", "Status:Port must be 1-65535; it is 0." },
        { "--Status:Port=70000", "Status:Port must be 1-65535; it is 70000." },
        { "--Status:Port=web", "Status:Port 'web' is not a whole number" },
        { "--Status:AccessToken=short", "Status:AccessToken has 5 characters; use at least 16" },
        { "--Status:AccessToken=0123456789abcdef\"<>", "Status:AccessToken holds a character an Authorization header cannot carry" },
        { "--Status:TraceFrames=5", "Status:TraceFrames must be 10-10000; it is 5." },
        { "--Status:RefreshInterval=50ms", "Status:RefreshInterval must be 100ms to 10s; it is 50 ms." },
        { "--Status:RefreshInterval=1", "Status:RefreshInterval '1' has no unit" },
        { "--Status:Adress=127.0.0.1", "Status:Adress is not a setting here" },
        { "--Status:Enabled=false --Status:Prot=80", "Status:Prot is not a setting here" },
        { "--Stauts:Port=80", "Stauts is not a section the gateway reads; did you mean Status?" },
    };

    [Theory]
    [MemberData(nameof(Mistakes))]
    public async Task A_mistake_exits_2_with_one_message_naming_its_key(string arguments, string expected)
    {
        var args = new List<string>
        {
            "--HostLink:Links:plc:Tcp=127.0.0.1:9",
            "--HostLink:Links:plc:Groups:levels:Address=D100",
            "--Logging:LogLevel:Default=Warning",
        };
        args.AddRange(arguments.Split(' '));
        // An empty content root: no appsettings.json but these arguments.
        string root = Directory.CreateTempSubdirectory("ohl-status-config-").FullName;
        args.AddRange(["--contentRoot", root]);
        var error = new StringWriter();

        Task<int> run = GatewayProgram.RunAsync(args.ToArray(), error);
        await Eventually.UntilAsync(() => run.IsCompleted, $"{arguments} stops the start", patience: TimeSpan.FromSeconds(60));
        Directory.Delete(root, recursive: true);

        string output = error.ToString();
        (await run).Should().Be(2, output);
        output.Split("the configuration is not valid").Should().HaveCount(2, "one message: {0}", output);
        output.Should().Contain(expected);
        output.Split('\n').Count(l => l.TrimStart().StartsWith("- ", StringComparison.Ordinal)).Should().Be(1, "one problem: {0}", output);
        output.Should().NotMatchRegex(@"(?m)^\s+at ", "no stack trace: {0}", output);
    }

    [Fact]
    public void The_defaults_are_this_machine_only_on_port_9680()
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(9, broker: null).Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal)).ToDictionary(k => k.Key, k => k.Value);
        MqttGatewayConfig.Group(config, "levels", "D100");
        config["Status:Enabled"] = "true";
        using IHost host = MqttGatewayConfig.Build(config, new CapturingLoggerProvider());

        StatusOptions options = host.Services.GetRequiredService<IOptions<StatusOptions>>().Value;
        options.IPAddress.Should().Be(IPAddress.Loopback);
        options.Port.Should().Be(9680);
        options.HasToken.Should().BeFalse();
        options.TraceFrames.Should().Be(500);
        options.RefreshInterval.Should().Be(TimeSpan.FromMilliseconds(500));
    }

    [Theory]
    [InlineData(null)]
    [InlineData("false")]
    public async Task Without_the_section_or_disabled_nothing_of_the_page_is_made_and_nothing_listens(string? enabled)
    {
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlc(new VirtualPlcOptions { Units = [0] }));
        Dictionary<string, string?> config = StatusGateway.Configuration(simulator);
        config.Remove("Status:RefreshInterval");
        if (enabled is null)
        {
            config.Remove("Status:Port");
        }
        else
        {
            config["Status:Enabled"] = enabled;
        }

        int port = enabled is null ? StatusOptions.DefaultPort : int.Parse(config["Status:Port"]!, System.Globalization.CultureInfo.InvariantCulture);
        MqttGatewayConfig.Group(config, "levels", "D100", intervalMs: 50);
        var logs = new CapturingLoggerProvider();
        using IHost host = MqttGatewayConfig.Build(config, logs);
        await host.StartAsync();
        try
        {
            long answers = simulator.Answers;
            await simulator.WaitForAnswersAsync(answers, 3, TimeSpan.FromSeconds(30));
            host.Services.GetService<StatusServer>().Should().BeNull();
            host.Services.GetService<TagBoard>().Should().BeNull();
            host.Services.GetServices<IHostedService>().Should().NotContain(s => s.GetType().Namespace == typeof(StatusServer).Namespace);
            host.Services.GetServices<ITagOutput>().Should().NotContain(o => o.GetType().Namespace == typeof(StatusServer).Namespace, "the polling reports to no store of the page");
            logs.WithEvent(StatusLog.Events.Started).Should().BeEmpty();
            if (enabled is not null)
            {
                // The port it would have had is not listened on.
                using var probe = new TcpClient();
                Func<Task> connect = () => probe.ConnectAsync(IPAddress.Loopback, port);
                await connect.Should().ThrowAsync<SocketException>();
            }
        }
        finally
        {
            await host.StopAsync();
        }
    }

    [Fact]
    public async Task A_port_in_use_is_one_line_and_exit_code_2()
    {
        using var taken = new TcpListener(IPAddress.Loopback, 0);
        taken.Start();
        int port = ((IPEndPoint)taken.LocalEndpoint).Port;
        await using GatewayProcess process = GatewayProcess.Start(
        [
            "--HostLink:Links:plc:Tcp=127.0.0.1:9",
            "--HostLink:Links:plc:Groups:g:Address=D0",
            $"--Status:Port={port}",
            "--Logging:LogLevel:Default=Warning",
        ]);
        if (await process.WaitForExitAsync(TimeSpan.FromSeconds(60)) is null)
        {
            await process.KillAsync();
        }

        string output = process.Output;
        process.ExitCode.Should().Be(2, output);
        output.Should().Contain($"Status:Address 127.0.0.1 and Status:Port {port}: the status page cannot listen there");
        output.Split('\n').Count(l => l.Contains("cannot listen", StringComparison.Ordinal)).Should().Be(1, "one line says it: {0}", output);
        output.Should().NotMatchRegex(@"(?m)^\s+at ", "no stack trace: {0}", output).And.NotContain("Exception");
    }
}
