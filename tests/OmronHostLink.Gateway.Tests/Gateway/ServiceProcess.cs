using System.Diagnostics;
using System.Runtime.InteropServices;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The worker running as a separate process the way systemd starts a service. Microsoft.Extensions.Hosting.Systemd
/// takes a process for a systemd service when its parent process is called <c>systemd</c> (or when it is PID 1 with
/// <c>NOTIFY_SOCKET</c> or <c>LISTEN_PID</c> set, as in a container), so the worker is started by <c>/bin/sh</c> run
/// through a link named <c>systemd</c>; the shell waits for it and exits with its exit code.
/// </summary>
internal sealed class ServiceProcess : IAsyncDisposable
{
    private readonly Process _parent;
    private readonly string _directory;
    private readonly List<string> _output = new();

    private ServiceProcess(Process parent, string directory, int workerPid)
    {
        _parent = parent;
        _directory = directory;
        WorkerPid = workerPid;
    }

    /// <summary>The worker's process id (the child of the process named systemd).</summary>
    public int WorkerPid { get; }

    /// <summary>Every line written so far to stdout and stderr.</summary>
    public string[] Output
    {
        get
        {
            lock (_output)
            {
                return _output.ToArray();
            }
        }
    }

    /// <summary>
    /// Starts <c>OmronHostLink.Gateway</c> (from beside the test assembly) with <paramref name="args"/> and
    /// <paramref name="environment"/>, in an empty working directory (so no appsettings.json is read).
    /// </summary>
    public static async Task<ServiceProcess> StartUnderSystemdAsync(IEnumerable<string> args, IReadOnlyDictionary<string, string> environment)
    {
        string directory = Path.Combine(Path.GetTempPath(), $"ohl-service-{Guid.NewGuid():N}");
        Directory.CreateDirectory(directory);
        string parentPath = Path.Combine(directory, "systemd");
        File.CreateSymbolicLink(parentPath, "/bin/sh");
        string pidFile = Path.Combine(directory, "worker.pid");

        var start = new ProcessStartInfo(parentPath)
        {
            UseShellExecute = false,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            WorkingDirectory = directory,
        };
        start.ArgumentList.Add("-c");
        start.ArgumentList.Add("\"$@\" & echo $! > \"$WORKER_PID_FILE\"; wait $!");
        start.ArgumentList.Add("systemd");
        start.ArgumentList.Add(DotnetHost());
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "OmronHostLink.Gateway.dll"));
        foreach (string arg in args)
        {
            start.ArgumentList.Add(arg);
        }

        start.Environment["WORKER_PID_FILE"] = pidFile;
        start.Environment["DOTNET_ENVIRONMENT"] = "Production";
        start.Environment.Remove("LISTEN_PID");
        start.Environment.Remove("LISTEN_FDS");
        foreach ((string name, string value) in environment)
        {
            start.Environment[name] = value;
        }

        var parent = new Process { StartInfo = start };
        parent.Start();
        int pid = await ReadPidAsync(parent, pidFile);
        var process = new ServiceProcess(parent, directory, pid);
        parent.OutputDataReceived += (_, e) => process.Add(e.Data);
        parent.ErrorDataReceived += (_, e) => process.Add(e.Data);
        parent.BeginOutputReadLine();
        parent.BeginErrorReadLine();
        return process;
    }

    /// <summary>The first output line that satisfies <paramref name="predicate"/>, waiting at most <paramref name="timeout"/>.</summary>
    public async Task<string?> WaitForLineAsync(Func<string, bool> predicate, TimeSpan timeout)
    {
        var clock = Stopwatch.StartNew();
        while (true)
        {
            string? line = Output.FirstOrDefault(predicate);
            if (line is not null || clock.Elapsed > timeout || _parent.HasExited)
            {
                return line ?? Output.FirstOrDefault(predicate);
            }

            await Task.Delay(50);
        }
    }

    /// <summary>Sends a signal (TERM, KILL…) to the worker, as systemctl stop does.</summary>
    public void Signal(string name)
    {
        using var kill = Process.Start(new ProcessStartInfo("/bin/sh") { ArgumentList = { "-c", $"kill -{name} {WorkerPid}" }, UseShellExecute = false })!;
        kill.WaitForExit();
        if (kill.ExitCode != 0)
        {
            throw new InvalidOperationException($"kill -{name} {WorkerPid} failed with exit code {kill.ExitCode}.");
        }
    }

    /// <summary>The worker's exit code (through its parent shell), or null if it is still running after <paramref name="timeout"/>.</summary>
    public async Task<int?> WaitForExitAsync(TimeSpan timeout)
    {
        using var cts = new CancellationTokenSource(timeout);
        try
        {
            await _parent.WaitForExitAsync(cts.Token);
            return _parent.ExitCode;
        }
        catch (OperationCanceledException)
        {
            return null;
        }
    }

    /// <summary>Output and state for a failure message.</summary>
    public override string ToString()
        => $"worker pid {WorkerPid}, {(_parent.HasExited ? $"exited with {_parent.ExitCode}" : "running")}; output:{Environment.NewLine}{string.Join(Environment.NewLine, Output)}";

    public async ValueTask DisposeAsync()
    {
        if (!_parent.HasExited)
        {
            try
            {
                Signal("KILL");
            }
            catch (InvalidOperationException)
            {
                // Already gone.
            }

            _parent.Kill();
            await _parent.WaitForExitAsync();
        }

        _parent.Dispose();
        Directory.Delete(_directory, recursive: true);
    }

    private void Add(string? line)
    {
        if (line is not null)
        {
            lock (_output)
            {
                _output.Add(line);
            }
        }
    }

    private static async Task<int> ReadPidAsync(Process parent, string pidFile)
    {
        var clock = Stopwatch.StartNew();
        while (clock.Elapsed < TimeSpan.FromSeconds(10))
        {
            // The shell writes "<pid>\n"; a read between its open and its write sees an empty file.
            if (File.Exists(pidFile) && File.ReadAllText(pidFile) is { Length: > 1 } text && text.EndsWith('\n'))
            {
                return int.Parse(text, System.Globalization.CultureInfo.InvariantCulture);
            }

            if (parent.HasExited)
            {
                break;
            }

            await Task.Delay(20);
        }

        string output = parent.HasExited ? await parent.StandardError.ReadToEndAsync() : string.Empty;
        throw new InvalidOperationException($"The worker's process id did not appear in {pidFile}. {output}");
    }

    /// <summary>The dotnet host running this test, so the worker runs on the same runtime.</summary>
    private static string DotnetHost()
    {
        string? current = Environment.ProcessPath;
        if (current is not null && Path.GetFileNameWithoutExtension(current) == "dotnet")
        {
            return current;
        }

        // <root>/shared/Microsoft.NETCore.App/<version>/ → <root>/dotnet
        string candidate = Path.GetFullPath(Path.Combine(RuntimeEnvironment.GetRuntimeDirectory(), "..", "..", "..", "dotnet"));
        return File.Exists(candidate) ? candidate : "dotnet";
    }
}
