using System.Diagnostics;
using System.Globalization;
using System.Text;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>The worker as a separate process, killed outright: the broker publishes its last will.</summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttLastWillTests(ITestOutputHelper output)
{
    [Fact]
    public async Task A_killed_worker_is_reported_offline_by_its_last_will()
    {
        await using MosquittoBroker broker = await MosquittoBroker.StartAsync();
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [5]);
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        string status = $"{MqttGatewayConfig.Prefix}/status/worker-kill";
        await using TestSubscriber subscriber = await TestSubscriber.ConnectAsync(broker, [status, MqttGatewayConfig.Topic("level")]);

        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker, clientId: "worker-kill");
        MqttGatewayConfig.Group(config, "level", "D100", intervalMs: 50);
        var log = new StringBuilder();
        DirectoryInfo empty = Directory.CreateTempSubdirectory("ohl-worker-");
        using Process worker = StartWorkerProcess(config, empty.FullName, log);
        try
        {
            await subscriber.WaitUntilAsync(ms => ms.Any(m => m.Topic == status && m.Payload == "online") && ms.Any(m => m.Topic == MqttGatewayConfig.Topic("level")), "the worker process is online and publishing");

            worker.Kill(); // SIGKILL: no clean disconnect, no "offline" of its own
            await worker.WaitForExitAsync();

            await subscriber.WaitUntilAsync(ms => ms.Any(m => m.Topic == status && m.Payload == "offline"), "the broker publishes the last will");
            subscriber.PayloadsOn(status).Should().Equal("online", "offline");
            await using TestSubscriber late = await TestSubscriber.ConnectAsync(broker, [status]);
            ReceivedMessage retained = await late.WaitForAsync(status);
            retained.Payload.Should().Be("offline", "the last will is retained");
            retained.Retain.Should().BeTrue();
        }
        finally
        {
            if (!worker.HasExited)
            {
                worker.Kill();
            }

            lock (log)
            {
                output.WriteLine("worker process:" + Environment.NewLine + log);
            }

            output.WriteLine("mosquitto:" + Environment.NewLine + broker.Log);
            empty.Delete(recursive: true);
        }
    }

    /// <summary>Runs the worker's own executable with the configuration on its command line, in an empty directory.</summary>
    private static Process StartWorkerProcess(Dictionary<string, string?> config, string directory, StringBuilder log)
    {
        string dll = Path.Combine(AppContext.BaseDirectory, "OmronHostLink.Gateway.dll");
        string dotnet = Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host && File.Exists(host)
            ? host
            : MosquittoBroker.Find("dotnet", "/usr/bin/dotnet", "/usr/share/dotnet/dotnet", "/usr/lib/dotnet/dotnet") ?? "dotnet";
        var startInfo = new ProcessStartInfo(dotnet)
        {
            RedirectStandardError = true,
            RedirectStandardOutput = true,
            UseShellExecute = false,
            // No appsettings.json there: the command line is the whole configuration.
            WorkingDirectory = directory,
        };
        startInfo.Environment["DOTNET_ENVIRONMENT"] = "Production";
        startInfo.ArgumentList.Add(dll);
        foreach ((string key, string? value) in config)
        {
            startInfo.ArgumentList.Add(string.Create(CultureInfo.InvariantCulture, $"--{key}={value}"));
        }

        var process = new Process { StartInfo = startInfo };
        DataReceivedEventHandler append = (_, e) =>
        {
            if (e.Data is not null)
            {
                lock (log)
                {
                    log.AppendLine(e.Data);
                }
            }
        };
        process.OutputDataReceived += append;
        process.ErrorDataReceived += append;
        process.Start();
        process.BeginOutputReadLine();
        process.BeginErrorReadLine();
        return process;
    }
}
