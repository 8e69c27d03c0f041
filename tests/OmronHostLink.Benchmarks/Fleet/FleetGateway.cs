using System.ComponentModel;
using System.Diagnostics;
using System.Globalization;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using OmronHostLink.Benchmarks.Scale;

namespace OmronHostLink.Benchmarks.Fleet;

/// <summary>
/// One gateway of the fleet as a separate process, configured by a generated <c>appsettings.json</c>; its console log
/// (single-line) is read as it comes: every value it read (event 1001, logged on change) by link, and its warnings.
/// </summary>
internal sealed partial class FleetGateway : ProgramProcess
{
    private readonly Dictionary<string, SortedSet<int>> _read = new(StringComparer.Ordinal);
    private readonly BoundedLog _warnings = new(30);
    private long _warningCount;

    private FleetGateway(ProcessStartInfo start, string directory, string name)
        : base(start, ownedDirectory: directory, keepLines: 200)
    {
        Name = name;
    }

    /// <summary>The gateway's name: its MQTT client id, its edge node id, its topic prefix's last level.</summary>
    public string Name { get; }

    /// <summary>Lines logged at Warning or above.</summary>
    public long Warnings => Interlocked.Read(ref _warningCount);

    /// <summary>The last warnings and errors.</summary>
    public string WarningLines => _warnings.ToString();

    /// <summary>The values read from each link's counter, by link name.</summary>
    public IReadOnlyDictionary<string, int[]> Read()
    {
        lock (_read)
        {
            return _read.ToDictionary(r => r.Key, r => r.Value.ToArray(), StringComparer.Ordinal);
        }
    }

    /// <summary>Writes <paramref name="settings"/> as the gateway's appsettings.json and starts it.</summary>
    public static async Task<FleetGateway> StartAsync(string assembly, string name, JsonObject settings, CancellationToken cancellationToken)
    {
        (ProcessStartInfo start, string directory) = await WorkerProcess.PrepareAsync(assembly, "ohl-fleet-" + name + "-", settings, cancellationToken).ConfigureAwait(false);
        var gateway = new FleetGateway(start, directory, name);
        try
        {
            gateway.Launch();
        }
        catch (Win32Exception e)
        {
            await gateway.DisposeAsync().ConfigureAwait(false);
            throw new InvalidOperationException($"The gateway could not be started: {e.Message}", e);
        }

        ChildProcesses.Add(gateway.Process);
        return gateway;
    }

    /// <summary>Stops the gateway with SIGTERM, killing it after 30 s.</summary>
    public async Task<bool> StopAsync()
    {
        bool graceful = await StopAsync(TimeSpan.FromSeconds(30)).ConfigureAwait(false);
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
        Match value = ValueLine().Match(line);
        if (value.Success)
        {
            lock (_read)
            {
                string link = value.Groups["link"].Value;
                if (!_read.TryGetValue(link, out SortedSet<int>? values))
                {
                    _read[link] = values = [];
                }

                values.Add(int.Parse(value.Groups["value"].Value, CultureInfo.InvariantCulture));
            }
        }
        else if (line.StartsWith("warn:", StringComparison.Ordinal) || line.StartsWith("fail:", StringComparison.Ordinal) || line.StartsWith("crit:", StringComparison.Ordinal))
        {
            Interlocked.Increment(ref _warningCount);
            _warnings.Add(line);
        }
    }

    [GeneratedRegex(@"\[1001\] (?<link>\S+)/counter: unit 0 D0 = (?<value>\d+)$")]
    private static partial Regex ValueLine();
}
