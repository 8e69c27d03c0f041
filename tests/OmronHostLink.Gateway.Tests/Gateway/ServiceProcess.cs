using System.Diagnostics;
using OmronHostLink.Gateway.Tests.Telemetry;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The worker running as a separate process the way systemd starts a service. Microsoft.Extensions.Hosting.Systemd
/// takes a process for a systemd service when its parent process is called <c>systemd</c> (or when it is PID 1 with
/// <c>NOTIFY_SOCKET</c> or <c>LISTEN_PID</c> set, as in a container), so the worker is started by <c>/bin/sh</c> run
/// through a link named <c>systemd</c>; the shell waits for it and exits with its exit code. Signals go to the worker;
/// the output, the exit and disposal are the shell's, which the worker's are.
/// </summary>
internal sealed class ServiceProcess : ProgramProcess
{
    private ServiceProcess(ProcessStartInfo start, string directory)
        : base(start, ownedDirectory: directory)
    {
    }

    /// <summary>The worker's process id (the child of the process named systemd).</summary>
    public int WorkerPid { get; private set; }

    /// <summary>
    /// Starts <c>OmronHostLink.Gateway</c> (from beside the test assembly) with <paramref name="args"/> and
    /// <paramref name="environment"/>, in an empty working directory (so no appsettings.json is read).
    /// </summary>
    public static async Task<ServiceProcess> StartUnderSystemdAsync(IEnumerable<string> args, IReadOnlyDictionary<string, string> environment)
    {
        string directory = NewDirectory("ohl-service-");
        string parentPath = Path.Combine(directory, "systemd");
        File.CreateSymbolicLink(parentPath, "/bin/sh");
        string pidFile = Path.Combine(directory, "worker.pid");

        var start = new ProcessStartInfo(parentPath) { WorkingDirectory = directory };
        start.ArgumentList.Add("-c");
        start.ArgumentList.Add("\"$@\" & echo $! > \"$WORKER_PID_FILE\"; wait $!");
        start.ArgumentList.Add("systemd");
        start.ArgumentList.Add(DotnetHost);
        start.ArgumentList.Add(GatewayProcess.Assembly);
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

        var service = new ServiceProcess(start, directory);
        try
        {
            service.Launch();
            service.WorkerPid = await service.ReadPidAsync(pidFile);
            return service;
        }
        catch
        {
            await service.DisposeAsync();
            throw;
        }
    }

    /// <summary>Sends a signal (<see cref="ProgramProcess.SigTerm"/>, <see cref="ProgramProcess.SigKill"/>…) to the worker, as systemctl stop does.</summary>
    public override void Signal(int signal) => SendSignal(WorkerPid, signal);

    /// <summary>Output and state for a failure message.</summary>
    public override string ToString() => $"worker pid {WorkerPid}, {base.ToString()}";

    private async Task<int> ReadPidAsync(string pidFile)
    {
        // The shell writes "<pid>\n"; a read between its open and its write sees an empty file.
        string? text = null;
        bool Written() => File.Exists(pidFile) && File.ReadAllText(pidFile) is { Length: > 1 } t && t.EndsWith('\n') && (text = t) is not null;
        try
        {
            await Eventually.UntilAsync(() => Written() || HasExited, "the worker's process id is written", patience: TimeSpan.FromSeconds(10));
        }
        catch (TimeoutException)
        {
        }

        return text is not null || Written()
            ? int.Parse(text!, System.Globalization.CultureInfo.InvariantCulture)
            : throw new InvalidOperationException($"The worker's process id did not appear in {pidFile}. {Output}");
    }
}
