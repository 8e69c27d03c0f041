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
/// read as it comes: cycle overruns (event 1007, "N tick(s) skipped") are counted and warnings kept.
/// </summary>
internal sealed partial class WorkerProcess : IAsyncDisposable
{
    private readonly Process _process;
    private readonly string _directory;
    private readonly BoundedLog _log = new(400);
    private readonly BoundedLog _warnings = new(20);
    private long _overrunEvents;
    private long _skippedTicks;
    private long _warningCount;

    private WorkerProcess(Process process, string directory)
    {
        _process = process;
        _directory = directory;
    }

    public int ProcessId => _process.Id;

    public bool HasExited => _process.HasExited;

    /// <summary>Event 1007 lines so far: a poll group found one or more of its ticks already past when it finished.</summary>
    public long OverrunEvents => Interlocked.Read(ref _overrunEvents);

    /// <summary>Ticks skipped in total, as event 1007 reports them.</summary>
    public long SkippedTicks => Interlocked.Read(ref _skippedTicks);

    /// <summary>Lines logged at Warning or above so far.</summary>
    public long Warnings => Interlocked.Read(ref _warningCount);

    /// <summary>The last warnings and errors.</summary>
    public string WarningLines => _warnings.ToString();

    /// <summary>The last lines the worker wrote.</summary>
    public string Log => _log.ToString();

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
        string directory = Directory.CreateTempSubdirectory("ohl-scale-worker-").FullName;
        await File.WriteAllTextAsync(
            Path.Combine(directory, "appsettings.json"),
            settings.ToJsonString(new JsonSerializerOptions { WriteIndented = true }),
            cancellationToken).ConfigureAwait(false);

        var startInfo = new ProcessStartInfo(FindDotnet())
        {
            RedirectStandardError = true,
            RedirectStandardOutput = true,
            UseShellExecute = false,
            WorkingDirectory = directory,
        };
        startInfo.Environment["DOTNET_ENVIRONMENT"] = "Production";
        startInfo.ArgumentList.Add(workerAssembly);
        // The generated file is the whole configuration: the content root is its directory, not the worker's own.
        startInfo.ArgumentList.Add("--contentRoot");
        startInfo.ArgumentList.Add(directory);
        var process = new Process { StartInfo = startInfo };
        var worker = new WorkerProcess(process, directory);
        process.OutputDataReceived += (_, e) => worker.Read(e.Data);
        process.ErrorDataReceived += (_, e) => worker.Read(e.Data);
        try
        {
            process.Start();
        }
        catch (Win32Exception e)
        {
            Directory.Delete(directory, recursive: true);
            throw new InvalidOperationException($"The worker could not be started ({startInfo.FileName} {workerAssembly}): {e.Message}", e);
        }

        ChildProcesses.Add(process);
        process.BeginOutputReadLine();
        process.BeginErrorReadLine();
        return worker;
    }

    /// <summary>Stops the worker as a service manager would (SIGTERM), killing it if it takes more than 20 s.</summary>
    /// <returns>Whether it stopped by itself.</returns>
    public Task<bool> StopAsync() => ChildProcesses.StopAsync(_process, TimeSpan.FromSeconds(20));

    public async ValueTask DisposeAsync()
    {
        await StopAsync().ConfigureAwait(false);
        _process.Dispose();
        try
        {
            Directory.Delete(_directory, recursive: true);
        }
        catch (IOException)
        {
        }
    }

    private static string FindDotnet()
    {
        if (Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } host && File.Exists(host))
        {
            return host;
        }

        foreach (string dir in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
        {
            string candidate = Path.Combine(dir, "dotnet");
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        return new[] { "/usr/bin/dotnet", "/usr/share/dotnet/dotnet", "/usr/lib/dotnet/dotnet" }.FirstOrDefault(File.Exists) ?? "dotnet";
    }

    [GeneratedRegex(@"\[1007\].*?(\d+) tick\(s\) skipped")]
    private static partial Regex OverrunLine();

    private void Read(string? line)
    {
        if (line is null)
        {
            return;
        }

        _log.Add(line);
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
}
