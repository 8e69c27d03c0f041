using System.ComponentModel;
using System.Diagnostics;
using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Text;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// Mosquitto on a free 127.0.0.1 port with a generated configuration (anonymous, no persistence), in a directory of
/// its own; stopped with SIGTERM (killed if it does not go) and the directory deleted on dispose.
/// </summary>
internal sealed class MosquittoProcess : IAsyncDisposable
{
    private static readonly TimeSpan StartTimeout = TimeSpan.FromSeconds(10);
    private readonly Process _process;
    private readonly string _directory;
    private readonly BoundedLog _log = new(200);

    private MosquittoProcess(Process process, string directory, int port)
    {
        _process = process;
        _directory = directory;
        Port = port;
    }

    public int Port { get; }

    public int ProcessId => _process.Id;

    /// <summary>The last lines the broker logged (warnings and errors only).</summary>
    public string Log => _log.ToString();

    public static async Task<MosquittoProcess> StartAsync(CancellationToken cancellationToken)
    {
        string executable = new[] { "/usr/sbin/mosquitto", "/usr/local/sbin/mosquitto", "/usr/bin/mosquitto" }.FirstOrDefault(File.Exists)
            ?? throw new InvalidOperationException("mosquitto is not installed (looked in /usr/sbin, /usr/local/sbin, /usr/bin). Debian/Ubuntu: apt-get install mosquitto mosquitto-clients.");
        string directory = Directory.CreateTempSubdirectory("ohl-scale-mosquitto-").FullName;
        int port = FreePort();
        var conf = new StringBuilder();
        conf.AppendLine(CultureInfo.InvariantCulture, $"listener {port} 127.0.0.1");
        conf.AppendLine("allow_anonymous true");
        conf.AppendLine("persistence false");
        // The benchmark's subscriber takes everything with QoS 1: let the broker queue for it rather than drop.
        conf.AppendLine("max_queued_messages 1000000");
        conf.AppendLine("log_dest stderr");
        conf.AppendLine("log_type error");
        conf.AppendLine("log_type warning");
        conf.AppendLine("connection_messages false");
        if (Environment.UserName == "root")
        {
            // Started as root, mosquitto would switch to the user "mosquitto".
            conf.AppendLine("user root");
        }

        string confFile = Path.Combine(directory, "mosquitto.conf");
        await File.WriteAllTextAsync(confFile, conf.ToString(), cancellationToken).ConfigureAwait(false);

        var startInfo = new ProcessStartInfo(executable)
        {
            RedirectStandardError = true,
            RedirectStandardOutput = true,
            UseShellExecute = false,
            WorkingDirectory = directory,
        };
        startInfo.ArgumentList.Add("-c");
        startInfo.ArgumentList.Add(confFile);
        var process = new Process { StartInfo = startInfo };
        var broker = new MosquittoProcess(process, directory, port);
        process.ErrorDataReceived += (_, e) => broker._log.Add(e.Data);
        process.OutputDataReceived += (_, e) => broker._log.Add(e.Data);
        try
        {
            process.Start();
        }
        catch (Win32Exception e)
        {
            Directory.Delete(directory, recursive: true);
            throw new InvalidOperationException($"mosquitto ({executable}) could not be started: {e.Message}", e);
        }

        ChildProcesses.Add(process);
        process.BeginErrorReadLine();
        process.BeginOutputReadLine();
        try
        {
            var clock = Stopwatch.StartNew();
            while (!await AcceptsAsync(port).ConfigureAwait(false))
            {
                if (process.HasExited)
                {
                    throw new InvalidOperationException($"mosquitto exited with code {process.ExitCode} while starting:\n{broker.Log}");
                }

                if (clock.Elapsed > StartTimeout)
                {
                    throw new InvalidOperationException($"mosquitto did not listen on 127.0.0.1:{port} within {StartTimeout.TotalSeconds} s:\n{broker.Log}");
                }

                await Task.Delay(50, cancellationToken).ConfigureAwait(false);
            }
        }
        catch
        {
            await broker.DisposeAsync().ConfigureAwait(false);
            throw;
        }

        return broker;
    }

    public async ValueTask DisposeAsync()
    {
        await ChildProcesses.StopAsync(_process, TimeSpan.FromSeconds(5)).ConfigureAwait(false);
        _process.Dispose();
        try
        {
            Directory.Delete(_directory, recursive: true);
        }
        catch (IOException)
        {
        }
    }

    private static int FreePort()
    {
        using var probe = new TcpListener(IPAddress.Loopback, 0);
        probe.Start();
        int port = ((IPEndPoint)probe.LocalEndpoint).Port;
        probe.Stop();
        return port;
    }

    private static async Task<bool> AcceptsAsync(int port)
    {
        using var client = new TcpClient();
        try
        {
            await client.ConnectAsync(IPAddress.Loopback, port).ConfigureAwait(false);
            return true;
        }
        catch (SocketException)
        {
            return false;
        }
    }
}
