using System.ComponentModel;
using System.Diagnostics;
using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Text;

namespace OmronHostLink.Testing;

/// <summary>What a test broker requires of its clients.</summary>
public sealed class MosquittoSettings
{
    /// <summary>Users and passwords (a password file made with <c>mosquitto_passwd</c>); none for anonymous access.</summary>
    public Dictionary<string, string> Users { get; } = new(StringComparer.Ordinal);

    /// <summary>An ACL file's text (<c>acl_file</c>); null for none.</summary>
    public string? Acl { get; set; }

    /// <summary>Serve TLS with these certificates; null for plain TCP.</summary>
    public TestCertificates? Tls { get; set; }

    /// <summary>Keep retained messages and persistent sessions across a restart (<c>persistence</c>). Default true.</summary>
    public bool Persistence { get; set; } = true;

    /// <summary>
    /// The most messages the broker queues for one client (<c>max_queued_messages</c>); beyond it, it drops. Default
    /// 100,000; a benchmark whose subscriber takes everything raises it.
    /// </summary>
    public int MaxQueuedMessages { get; set; } = 100_000;
}

/// <summary>
/// A real Mosquitto broker on a free loopback port, with a generated configuration (<c>listener PORT 127.0.0.1</c>,
/// persistence in its own directory so a restart keeps retained messages and persistent sessions), for the tests and the
/// benchmarks. Mosquitto must be installed: the tests fail, not skip, without it.
/// </summary>
public sealed class MosquittoBroker : IAsyncDisposable
{
    private static readonly TimeSpan StartTimeout = TimeSpan.FromSeconds(10);
    private readonly StringBuilder _log = new();
    private readonly string _executable;
    private Process? _process;

    private MosquittoBroker(string directory, string executable, int port, MosquittoSettings settings)
    {
        Directory = directory;
        _executable = executable;
        Port = port;
        Settings = settings;
    }

    /// <summary>The broker's working directory: configuration, password file, persistence, certificates.</summary>
    public string Directory { get; }

    /// <summary>The TCP port on 127.0.0.1.</summary>
    public int Port { get; }

    /// <summary>What the broker requires.</summary>
    public MosquittoSettings Settings { get; }

    /// <summary>Whether the broker process runs.</summary>
    public bool IsRunning => _process is { HasExited: false };

    /// <summary>The broker's process while it runs (to sample its CPU time, or end it when its starter ends).</summary>
    public Process? Process => _process;

    /// <summary>What the broker has logged so far, across restarts (for failure messages).</summary>
    public string Log
    {
        get
        {
            lock (_log)
            {
                return _log.ToString();
            }
        }
    }

    /// <summary>Writes the configuration and starts the broker; returns once it accepts connections.</summary>
    public static async Task<MosquittoBroker> StartAsync(MosquittoSettings? settings = null)
    {
        settings ??= new MosquittoSettings();
        string executable = Find("mosquitto", "/usr/sbin/mosquitto", "/usr/local/sbin/mosquitto")
            ?? throw new InvalidOperationException(
                "mosquitto is not installed or not on PATH (looked in PATH, /usr/sbin and /usr/local/sbin); the MQTT tests need a real broker. Install it (Debian/Ubuntu: apt-get install mosquitto mosquitto-clients).");
        string directory = System.IO.Directory.CreateTempSubdirectory("ohl-mosquitto-").FullName;
        var broker = new MosquittoBroker(directory, executable, FreePort(), settings);
        try
        {
            await broker.WriteConfigurationAsync().ConfigureAwait(false);
            await broker.RestartAsync().ConfigureAwait(false);
            return broker;
        }
        catch
        {
            await broker.DisposeAsync().ConfigureAwait(false);
            throw;
        }
    }

    /// <summary>Starts the broker again on the same port with the same configuration and persistence (after <see cref="StopAsync"/>).</summary>
    public async Task RestartAsync()
    {
        if (IsRunning)
        {
            throw new InvalidOperationException("The broker is running.");
        }

        var startInfo = new ProcessStartInfo(_executable)
        {
            RedirectStandardError = true,
            RedirectStandardOutput = true,
            UseShellExecute = false,
            WorkingDirectory = Directory,
        };
        startInfo.ArgumentList.Add("-c");
        startInfo.ArgumentList.Add(Path.Combine(Directory, "mosquitto.conf"));
        var process = new Process { StartInfo = startInfo, EnableRaisingEvents = true };
        var exited = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        process.ErrorDataReceived += (_, e) => Append(e.Data);
        process.OutputDataReceived += (_, e) => Append(e.Data);
        process.Exited += (_, _) => exited.TrySetResult();
        try
        {
            process.Start();
        }
        catch (Win32Exception e)
        {
            process.Dispose();
            throw new InvalidOperationException($"mosquitto ({_executable}) could not be started: {e.Message}. Install it (Debian/Ubuntu: apt-get install mosquitto mosquitto-clients).", e);
        }

        process.BeginErrorReadLine();
        process.BeginOutputReadLine();
        _process = process;

        // Ready when the port accepts connections; a broker that exits (port taken, bad configuration) fails at once.
        var clock = Stopwatch.StartNew();
        using var tick = new PeriodicTimer(TimeSpan.FromMilliseconds(50));
        while (true)
        {
            if (exited.Task.IsCompleted)
            {
                throw new InvalidOperationException($"mosquitto exited with code {process.ExitCode} while starting.\n{Log}");
            }

            if (await AcceptsAsync(Port).ConfigureAwait(false))
            {
                return;
            }

            if (clock.Elapsed > StartTimeout)
            {
                throw new InvalidOperationException($"mosquitto did not listen on 127.0.0.1:{Port} within {StartTimeout.TotalSeconds} s.\n{Log}");
            }

            await Task.WhenAny(exited.Task, tick.WaitForNextTickAsync().AsTask()).ConfigureAwait(false);
        }
    }

    /// <summary>Stops the broker with SIGTERM (it saves its persistence file) and waits until it has exited.</summary>
    public async Task StopAsync()
    {
        Process? process = _process;
        if (process is null)
        {
            return;
        }

        _process = null;
        if (!process.HasExited)
        {
            ProgramProcess.SendSignal(process.Id, ProgramProcess.SigTerm);
            using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(10));
            try
            {
                await process.WaitForExitAsync(timeout.Token).ConfigureAwait(false);
            }
            catch (OperationCanceledException)
            {
                process.Kill();
                await process.WaitForExitAsync().ConfigureAwait(false);
            }
        }

        process.Dispose();
    }

    /// <summary>Stops the broker and deletes its directory.</summary>
    public async ValueTask DisposeAsync()
    {
        await StopAsync().ConfigureAwait(false);
        try
        {
            System.IO.Directory.Delete(Directory, recursive: true);
        }
        catch (IOException)
        {
        }
        catch (UnauthorizedAccessException)
        {
        }
    }

    /// <summary>A free TCP port on 127.0.0.1 (bound and released; the broker takes it next).</summary>
    public static int FreePort()
    {
        using var probe = new TcpListener(IPAddress.Loopback, 0);
        probe.Start();
        int port = ((IPEndPoint)probe.LocalEndpoint).Port;
        probe.Stop();
        return port;
    }

    /// <summary>Looks for an executable on PATH, then in the given places.</summary>
    public static string? Find(string name, params string[] fallbacks)
    {
        foreach (string dir in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
        {
            string candidate = Path.Combine(dir, name);
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        return fallbacks.FirstOrDefault(File.Exists);
    }

    private async Task WriteConfigurationAsync()
    {
        var conf = new StringBuilder();
        conf.AppendLine(CultureInfo.InvariantCulture, $"listener {Port} 127.0.0.1");
        if (Settings.Users.Count == 0)
        {
            conf.AppendLine("allow_anonymous true");
        }
        else
        {
            conf.AppendLine("allow_anonymous false");
            string passwords = Path.Combine(Directory, "passwd");
            string tool = Find("mosquitto_passwd", "/usr/bin/mosquitto_passwd", "/usr/local/bin/mosquitto_passwd")
                ?? throw new InvalidOperationException("mosquitto_passwd is not installed (Debian/Ubuntu: apt-get install mosquitto).");
            bool first = true;
            foreach ((string user, string password) in Settings.Users)
            {
                var args = new List<string> { "-b" };
                if (first)
                {
                    args.Add("-c");
                }

                args.AddRange([passwords, user, password]);
                await RunAsync(tool, args).ConfigureAwait(false);
                first = false;
            }

            conf.AppendLine(CultureInfo.InvariantCulture, $"password_file {passwords}");
        }

        if (Settings.Acl is { } acl)
        {
            string aclFile = Path.Combine(Directory, "acl");
            await File.WriteAllTextAsync(aclFile, acl).ConfigureAwait(false);
            conf.AppendLine(CultureInfo.InvariantCulture, $"acl_file {aclFile}");
        }

        if (Settings.Tls is { } tls)
        {
            tls.WriteBrokerFiles(Directory);
            conf.AppendLine(CultureInfo.InvariantCulture, $"cafile {Path.Combine(Directory, "ca.pem")}");
            conf.AppendLine(CultureInfo.InvariantCulture, $"certfile {Path.Combine(Directory, "server.pem")}");
            conf.AppendLine(CultureInfo.InvariantCulture, $"keyfile {Path.Combine(Directory, "server.key")}");
        }

        if (Settings.Persistence)
        {
            conf.AppendLine("persistence true");
            conf.AppendLine(CultureInfo.InvariantCulture, $"persistence_location {Directory}/");
        }
        else
        {
            conf.AppendLine("persistence false");
        }

        conf.AppendLine(CultureInfo.InvariantCulture, $"max_queued_messages {Settings.MaxQueuedMessages}");
        conf.AppendLine("log_dest stderr");
        conf.AppendLine("log_type error");
        conf.AppendLine("log_type warning");
        conf.AppendLine("log_type notice");
        conf.AppendLine("log_type information");
        conf.AppendLine("connection_messages true");
        if (Environment.UserName == "root")
        {
            // Started as root, mosquitto would switch to the user "mosquitto", which cannot write this directory.
            conf.AppendLine("user root");
        }

        await File.WriteAllTextAsync(Path.Combine(Directory, "mosquitto.conf"), conf.ToString()).ConfigureAwait(false);
    }

    private static async Task RunAsync(string tool, List<string> args)
    {
        var startInfo = new ProcessStartInfo(tool) { RedirectStandardError = true, RedirectStandardOutput = true, UseShellExecute = false };
        args.ForEach(startInfo.ArgumentList.Add);
        using Process process = Process.Start(startInfo)!;
        string errors = await process.StandardError.ReadToEndAsync().ConfigureAwait(false);
        await process.WaitForExitAsync().ConfigureAwait(false);
        if (process.ExitCode != 0)
        {
            throw new InvalidOperationException($"{tool} failed ({process.ExitCode}): {errors}");
        }
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

    private void Append(string? line)
    {
        if (line is null)
        {
            return;
        }

        lock (_log)
        {
            _log.AppendLine(line);
        }
    }
}
