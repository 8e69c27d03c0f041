using System.ComponentModel;
using System.Diagnostics;
using System.Globalization;
using System.Reflection;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// <c>src/OmronHostLink.Gateway</c> as a separate process (<c>dotnet OmronHostLink.Gateway.dll</c>), configured
/// only by an <c>appsettings.json</c> generated into an empty content root. Its console log (single-line format) is
/// read as it comes: cycle overruns (event 1007, "N tick(s) skipped") are counted and warnings kept; of the rest only
/// the last lines are kept.
/// </summary>
internal sealed partial class WorkerProcess : ProgramProcess
{
    private readonly BoundedLog _warnings = new(20);
    private long _overrunEvents;
    private long _skippedTicks;
    private long _warningCount;

    private WorkerProcess(ProcessStartInfo start, string directory)
        : base(start, ownedDirectory: directory, keepLines: 400)
    {
    }

    /// <summary>Event 1007 lines so far: a poll group found one or more of its ticks already past when it finished.</summary>
    public long OverrunEvents => Interlocked.Read(ref _overrunEvents);

    /// <summary>Ticks skipped in total, as event 1007 reports them.</summary>
    public long SkippedTicks => Interlocked.Read(ref _skippedTicks);

    /// <summary>Lines logged at Warning or above so far.</summary>
    public long Warnings => Interlocked.Read(ref _warningCount);

    /// <summary>The last warnings and errors.</summary>
    public string WarningLines => _warnings.ToString();

    /// <summary>The gateway assembly built with the benchmark (same configuration), or <paramref name="explicitPath"/>.</summary>
    public static string Locate(string? explicitPath)
    {
        string? path = explicitPath ?? typeof(WorkerProcess).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>()
            .FirstOrDefault(a => a.Key == "WorkerAssembly")?.Value;
        if (path is null || !File.Exists(path))
        {
            throw new InvalidOperationException(
                $"The gateway assembly '{path}' does not exist. Build it (dotnet build src/OmronHostLink.Gateway -c Release) or pass --worker <path to OmronHostLink.Gateway.dll>.");
        }

        return path;
    }

    /// <summary>Writes <paramref name="settings"/> as the worker's appsettings.json and starts the worker.</summary>
    public static async Task<WorkerProcess> StartAsync(string workerAssembly, JsonObject settings, CancellationToken cancellationToken)
    {
        (ProcessStartInfo start, string directory) = await PrepareAsync(workerAssembly, "ohl-scale-worker-", settings, cancellationToken).ConfigureAwait(false);
        var worker = new WorkerProcess(start, directory);
        try
        {
            worker.Launch();
        }
        catch (Win32Exception e)
        {
            await worker.DisposeAsync().ConfigureAwait(false);
            throw new InvalidOperationException($"The worker could not be started ({start.FileName} {workerAssembly}): {e.Message}", e);
        }

        ChildProcesses.Add(worker.Process);
        return worker;
    }

    /// <summary>
    /// Writes <paramref name="settings"/> as <c>appsettings.json</c> in a new directory and makes the command that runs
    /// the gateway on it: the generated file is the whole configuration (the content root is its directory).
    /// </summary>
    internal static async Task<(ProcessStartInfo Start, string Directory)> PrepareAsync(string gatewayAssembly, string directoryPrefix, JsonObject settings, CancellationToken cancellationToken)
    {
        string directory = NewDirectory(directoryPrefix);
        await File.WriteAllTextAsync(
            Path.Combine(directory, "appsettings.json"),
            settings.ToJsonString(new JsonSerializerOptions { WriteIndented = true }),
            cancellationToken).ConfigureAwait(false);
        ProcessStartInfo start = DotnetStart(gatewayAssembly, ["--contentRoot", directory]);
        start.WorkingDirectory = directory;
        start.Environment["DOTNET_ENVIRONMENT"] = "Production";
        return (start, directory);
    }

    /// <summary>Stops the worker as a service manager would (SIGTERM), killing it if it takes more than 20 s.</summary>
    /// <returns>Whether it stopped by itself.</returns>
    public async Task<bool> StopAsync()
    {
        bool graceful = await StopAsync(TimeSpan.FromSeconds(20)).ConfigureAwait(false);
        ChildProcesses.Remove(Process);
        return graceful;
    }

    protected override async ValueTask DisposeAsyncCore()
    {
        await StopAsync().ConfigureAwait(false);
        await base.DisposeAsyncCore().ConfigureAwait(false);
    }

    protected override void OnLine(string line)
    {
        if (line.Contains("[1007]", StringComparison.Ordinal))
        {
            Interlocked.Increment(ref _overrunEvents);
            Match m = OverrunLine().Match(line);
            Interlocked.Add(ref _skippedTicks, m.Success ? long.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture) : 1);
        }
        else if (line.StartsWith("warn:", StringComparison.Ordinal) || line.StartsWith("fail:", StringComparison.Ordinal) || line.StartsWith("crit:", StringComparison.Ordinal))
        {
            Interlocked.Increment(ref _warningCount);
            _warnings.Add(line);
        }
    }

    [GeneratedRegex(@"\[1007\].*?(\d+) tick\(s\) skipped")]
    private static partial Regex OverrunLine();
}
