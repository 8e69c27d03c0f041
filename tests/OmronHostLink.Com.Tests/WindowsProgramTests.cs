using System.Globalization;
using System.IO.Compression;
using System.Text.Json;
using System.Text.Json.Nodes;

namespace OmronHostLink.Com.Tests;

/// <summary>
/// The Windows zips build/package.sh makes, unzipped into the Wine prefix and run there as a plant runs them: hostlink.exe
/// against the simulator, and the gateway (win-x64, self-contained) with only its appsettings.json edited as
/// docs/install-windows.md says, publishing to Mosquitto with a password from Mqtt__Password, taking an allowlisted
/// write, and keeping its state in %ProgramData%\OmronHostLink.Gateway.
/// </summary>
[Collection(WineCollection.Name)]
public sealed class WindowsProgramTests(WineBed bed)
{
    private static readonly TimeSpan Timeout = TimeSpan.FromMinutes(2);

    [Fact]
    public async Task Hostlink_exe_reads_writes_and_monitors_the_simulator()
    {
        string folder = Unzip("hostlink-*-win-x64.zip", "hostlink");
        string exe = Path.Combine(folder, "hostlink.exe");
        await using Simulation simulation = await Simulation.StartAsync();

        ProcessResult read = await bed.RunAsync(bed.Wine64, [exe, "read", "D100", "10", "--json", "--tcp", simulation.Endpoint, "--set", Allowance], Timeout);
        read.ExitCode.Should().Be(0, read.Output);
        JsonNode document = JsonNode.Parse(read.Lines.Single())!;
        document["values"]!.AsArray().Select(v => (int)v!).Should().Equal(Enumerable.Range(1000, 10));

        ProcessResult write = await bed.RunAsync(bed.Wine64, [exe, "write", "D200", "1234", "4321", "--tcp", simulation.Endpoint, "--set", Allowance], Timeout);
        write.ExitCode.Should().Be(0, write.Output);
        simulation.Unit0.ReadWords("D200", 2).Should().Equal(1234, 4321);

        simulation.Unit0.Mode = PlcMode.Run;
        ProcessResult refused = await bed.RunAsync(bed.Wine64, [exe, "write", "D200", "1", "--tcp", simulation.Endpoint, "--set", Allowance], Timeout);
        refused.ExitCode.Should().Be(3, "exit 3 is a PLC end code: " + refused.Output);
        refused.Output.Should().Contain("RUN mode");

        await using WineProcess monitor = bed.Launch(bed.Wine64, [exe, "monitor", "D100", "--interval", "100ms", "--count", "100", "--json", "--tcp", simulation.Endpoint, "--set", Allowance]);
        await monitor.WaitForLineAsync(l => l.Contains("\"values\":[1000]", StringComparison.Ordinal), Timeout, "with D100's first value");
        simulation.Unit0.WriteWords("D100", [555]);
        await monitor.WaitForLineAsync(l => l.Contains("\"values\":[555]", StringComparison.Ordinal), Timeout, "with D100's new value");
        (await monitor.WaitForExitAsync(Timeout)).Should().Be(0, monitor.Output);
    }

    [Fact]
    public async Task The_gateway_zip_runs_with_only_its_configuration_edited()
    {
        string folder = Unzip("OmronHostLink.Gateway-*-win-x64.zip", "OmronHostLink.Gateway");
        File.Exists(Path.Combine(folder, "OmronHostLink.Gateway.exe")).Should().BeTrue();
        File.Exists(Path.Combine(folder, "deploy", "install-service.ps1")).Should().BeTrue("the service's install script ships in the zip");
        string state = Path.Combine(bed.Prefix, "drive_c", "ProgramData", "OmronHostLink.Gateway");
        if (Directory.Exists(state))
        {
            Directory.Delete(state, recursive: true);
        }

        await using Simulation simulation = await Simulation.StartAsync();
        var settings = new MosquittoSettings();
        settings.Users["gateway"] = "s3cret-gw";
        settings.Users["scada"] = "s3cret-scada";
        await using MosquittoBroker broker = await MosquittoBroker.StartAsync(settings);
        EditConfiguration(Path.Combine(folder, "appsettings.json"), simulation.Endpoint, broker.Port);

        await using WineProcess values = Subscribe(broker, "plant1/#");
        await using WineProcess gateway = bed.Launch(
            bed.Wine64,
            [Path.Combine(folder, "OmronHostLink.Gateway.exe")],
            new Dictionary<string, string> { ["Mqtt__Password"] = "s3cret-gw" },
            workingDirectory: folder);

        await values.WaitForLineAsync(l => l.StartsWith("plant1/line1/0/levels ", StringComparison.Ordinal) && l.Contains("[1000,1001,1002,1003]", StringComparison.Ordinal), Timeout, "with the levels group's values");
        simulation.Unit0.WriteWords("D101", [7]);
        await values.WaitForLineAsync(l => l.StartsWith("plant1/line1/0/levels ", StringComparison.Ordinal) && l.Contains("[1000,7,1002,1003]", StringComparison.Ordinal), Timeout, "with the changed value");

        ProcessResult publish = await ProcessResult.RunAsync(MosquittoClient("mosquitto_pub", broker, "scada", "s3cret-scada", "-t", "plant1/line1/0/setpoint/set", "-m", "2468", "-q", "1"), Timeout);
        publish.ExitCode.Should().Be(0, publish.Output);
        await values.WaitForLineAsync(l => l.StartsWith("plant1/line1/0/setpoint/set/result ", StringComparison.Ordinal), Timeout, "with the write's result");
        values.Lines.Single(l => l.StartsWith("plant1/line1/0/setpoint/set/result ", StringComparison.Ordinal)).Should().Contain("\"status\":\"done\"");
        simulation.Unit0.ReadWords("D300", 1).Should().Equal(2468);

        ProcessResult refused = await ProcessResult.RunAsync(MosquittoClient("mosquitto_pub", broker, "scada", "s3cret-scada", "-t", "plant1/line1/0/levels/set", "-m", "1", "-q", "1"), Timeout);
        refused.ExitCode.Should().Be(0, refused.Output);
        simulation.Unit0.ReadWords("D100", 1).Should().Equal(1000);

        Directory.Exists(state).Should().BeTrue($"the gateway keeps its state in %ProgramData%\\OmronHostLink.Gateway:\n{gateway.Output}");
        Directory.GetFiles(state).Select(Path.GetFileName).Should().Contain("gw-wine.queue.db", "the durable queue lives in the state folder");
        gateway.HasExited.Should().BeFalse(gateway.Output);
    }

    /// <summary>
    /// The turnaround allowance hostlink.exe is given: under Wine, on a test machine that builds and tests beside it, an
    /// answer can wait for a thread longer than the default.
    /// </summary>
    private const string Allowance = "TurnaroundAllowance=00:00:02";

    /// <summary>docs/install-windows.md's first step: the link, the groups, the broker, the writes; nothing else.</summary>
    private static void EditConfiguration(string path, string endpoint, int brokerPort)
    {
        JsonNode root = JsonNode.Parse(File.ReadAllText(path), documentOptions: new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip })!;
        JsonObject link = root["HostLink"]!["Links"]!["line1"]!.AsObject();
        link.Remove("Serial");
        link["Tcp"] = endpoint;
        // The gateway runs under Wine on a test machine that builds and tests beside it: its answers can wait for a thread
        // longer than the default allowance, as they can behind a serial-device server on a busy network.
        link["TurnaroundAllowance"] = "00:00:02";
        link["Groups"]!["setpoint"] = new JsonObject { ["Unit"] = 0, ["Address"] = "D300", ["Type"] = "word", ["Interval"] = "00:00:00.500", ["Writable"] = true };
        root["Mqtt"] = new JsonObject
        {
            ["Host"] = "127.0.0.1",
            ["Port"] = brokerPort,
            ["ClientId"] = "gw-wine",
            ["Username"] = "gateway",
            ["TopicPrefix"] = "plant1",
            ["Writes"] = new JsonObject { ["Enabled"] = true },
            ["DurableQueue"] = new JsonObject { ["Enabled"] = true },
        };
        File.WriteAllText(path, root.ToJsonString(new JsonSerializerOptions { WriteIndented = true }));
    }

    private WineProcess Subscribe(MosquittoBroker broker, string topic)
        => new(MosquittoClient("mosquitto_sub", broker, "scada", "s3cret-scada", "-t", topic, "-v"));

    private static System.Diagnostics.ProcessStartInfo MosquittoClient(string program, MosquittoBroker broker, string user, string password, params string[] arguments)
    {
        var start = new System.Diagnostics.ProcessStartInfo(program);
        foreach (string argument in (string[])["-h", "127.0.0.1", "-p", broker.Port.ToString(CultureInfo.InvariantCulture), "-u", user, "-P", password, .. arguments])
        {
            start.ArgumentList.Add(argument);
        }

        return start;
    }

    private string Unzip(string pattern, string name)
    {
        string folder = Path.Combine(bed.Prefix, "drive_c", name);
        if (Directory.Exists(folder))
        {
            Directory.Delete(folder, recursive: true);
        }

        ZipFile.ExtractToDirectory(bed.Artifact(pattern), folder);
        return folder;
    }
}
