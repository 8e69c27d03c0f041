using System.Diagnostics.Metrics;
using System.Text.Json;
using System.Threading.Channels;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Writes;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// Carries out DCMD metric writes one at a time, through the <see cref="TagWriter"/> that MQTT JSON writes use: only
/// with <c>Sparkplug:Writes:Enabled</c>, only to metrics of tags configured <c>Writable</c>, only with a value of the
/// type the metric's birth declared (in the field that type travels in) that the tag's type takes. Anything else is
/// refused and logged, and nothing reaches the PLC for it. Sparkplug has no reply to a command: the value written comes
/// back in the next DDATA, read from the PLC.
/// </summary>
/// <remarks>
/// A command is bounded before anything of it waits: a metric given several times is written once, with the last
/// value the command gives it, in the place of its last mention (so a value set before a trigger stays before it); a
/// command of more metric writes than the backlog holds, or than there is room for now, is refused whole, and the
/// refusal says how many writes it asked for (<see cref="WriteBacklog"/>, the bound of JSON commands).
/// </remarks>
internal sealed class SparkplugCommands
{
    /// <summary>How many unknown metrics a refusal names before it counts the rest.</summary>
    private const int NamesShown = 5;

    private readonly Channel<DeviceCommand> _commands = Channel.CreateUnbounded<DeviceCommand>(new UnboundedChannelOptions { SingleReader = true });
    private readonly WriteBacklog _backlog = new();
    private readonly SparkplugNode _node;
    private readonly TagWriter _writer;
    private readonly bool _enabled;
    private readonly ILogger _logger;
    private readonly Counter<long> _writes;

    /// <summary>Creates the processor.</summary>
    public SparkplugCommands(SparkplugOptions options, SparkplugNode node, OpenLinks links, IMeterFactory meterFactory, ILogger<SparkplugCommands> logger)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(meterFactory);
        _enabled = options.Writes.Enabled;
        _node = node;
        _writer = new TagWriter(links);
        _logger = logger;
        _writes = meterFactory.Create(GatewayNames.Meter).CreateCounter<long>("hostlink.gateway.sparkplug.writes", "{metric}", "DCMD metric writes by result: done, refused, failed.");
    }

    /// <summary>How many metric writes wait now.</summary>
    public int Waiting => _backlog.Waiting;

    /// <summary>
    /// Takes a DCMD from the MQTT client's receive path, never blocking it: reads and merges its metrics, and queues
    /// their writes if the backlog has room for all of them; otherwise refuses it whole.
    /// </summary>
    public void Accept(string deviceId, byte[] payload)
    {
        if (Plan(deviceId, payload) is not { Writes.Count: > 0 } command)
        {
            return;
        }

        int count = command.Writes.Count;
        if (count > WriteBacklog.Capacity)
        {
            RefusedWhole(deviceId, count, $"a DCMD may carry at most {WriteBacklog.Capacity} metric writes (each metric counted once)");
        }
        else if (!_backlog.TryReserve(count))
        {
            RefusedWhole(deviceId, count, $"{_backlog.Waiting} metric writes are waiting already and at most {WriteBacklog.Capacity} may; send it again later");
        }
        else if (!_commands.Writer.TryWrite(command))
        {
            // Stopped: nothing is carried out any more.
            _backlog.Release(count);
        }
    }

    /// <summary>Carries out the queued writes in the order they came until <paramref name="cancellationToken"/> is cancelled.</summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        try
        {
            await foreach (DeviceCommand command in _commands.Reader.ReadAllAsync(cancellationToken).ConfigureAwait(false))
            {
                foreach (MetricWrite write in command.Writes)
                {
                    try
                    {
                        await ExecuteAsync(command.Device, write, cancellationToken).ConfigureAwait(false);
                    }
                    catch (Exception e) when (e is not OperationCanceledException && e is not OutOfMemoryException)
                    {
                        // A bug must not end the loop: every later command would be ignored.
                        _writes.Add(1, new KeyValuePair<string, object?>("result", TagWriteStatus.Failed.Name()));
                        SparkplugLog.WriteCrashed(_logger, e, command.Device.Id, write.Label);
                    }
                    finally
                    {
                        _backlog.Release(1);
                    }
                }
            }
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            // Stopping.
        }
    }

    /// <summary>
    /// The writes of a DCMD: each metric it names once, with the last value it gives it, in the order of their last
    /// mention. Null, after logging why, for a command refused whole (no such device, not a Sparkplug B payload,
    /// writes disabled). Metrics the device does not have are refused and logged, together.
    /// </summary>
    internal DeviceCommand? Plan(string deviceId, byte[] payload)
    {
        SparkplugDevice? device = _node.Device(deviceId);
        IReadOnlyList<SparkplugCommandMetric>? metrics = SparkplugCommandMetric.Parse(payload);
        if (device is null || metrics is null)
        {
            RefusedWhole(deviceId, metrics?.Count ?? 0, device is null ? $"this edge node has no device {deviceId}" : "the payload is not a Sparkplug B payload");
            return null;
        }

        if (!_enabled)
        {
            RefusedWhole(deviceId, metrics.Count, "writes are disabled (Sparkplug:Writes:Enabled is false)");
            return null;
        }

        var last = new Dictionary<SparkplugMetric, MetricWrite>();
        var unknown = new List<string>();
        for (int i = 0; i < metrics.Count; i++)
        {
            SparkplugCommandMetric command = metrics[i];
            string label = command.Name ?? $"alias {command.Alias}";
            SparkplugMetric? metric = command.Name is { } name ? device.Metric(name) : command.Alias is { } alias ? device.Metric(alias) : null;
            if (metric is null)
            {
                if (!unknown.Contains(label))
                {
                    unknown.Add(label);
                }

                continue;
            }

            last[metric] = new MetricWrite(metric, label, command, i);
        }

        if (unknown.Count > 0)
        {
            string names = string.Join(", ", unknown.Take(NamesShown)) + (unknown.Count > NamesShown ? $" and {unknown.Count - NamesShown} more" : "");
            Refused(deviceId, names, $"device {deviceId} has no such metric.", unknown.Count);
        }

        return new DeviceCommand(device, last.Values.OrderBy(w => w.Position).ToList());
    }

    /// <summary>Checks and carries out one metric write.</summary>
    private async Task ExecuteAsync(SparkplugDevice device, MetricWrite write, CancellationToken cancellationToken)
    {
        SparkplugMetric metric = write.Metric;
        if (!write.Command.TryGetValue(metric.DataType, out JsonElement value, out string error))
        {
            Refused(device.Id, write.Label, $"{error} (the metric is {metric.DataType}).");
            return;
        }

        TagDefinition tag = device.Tags[metric.Tag];
        TagWriteOutcome outcome = await _writer.WriteAsync(tag, value, metric.Element < 0 ? null : metric.Element, cancellationToken).ConfigureAwait(false);
        if (outcome.Status == TagWriteStatus.Refused)
        {
            Refused(device.Id, write.Label, outcome.Error!);
            return;
        }

        _writes.Add(1, new KeyValuePair<string, object?>("result", outcome.Status.Name()));
        if (outcome.IsDone)
        {
            SparkplugLog.WriteDone(_logger, device.Id, write.Label, tag.Address.ToString(), value.GetRawText());
        }
        else
        {
            SparkplugLog.WriteFailed(_logger, device.Id, write.Label, tag.Address.ToString(), value.GetRawText(), outcome.Error!);
        }
    }

    private void Refused(string device, string metric, string reason, int count = 1)
    {
        _writes.Add(count, new KeyValuePair<string, object?>("result", TagWriteStatus.Refused.Name()));
        SparkplugLog.WriteRefused(_logger, device, metric, reason);
    }

    private void RefusedWhole(string device, int count, string reason)
    {
        _writes.Add(count, new KeyValuePair<string, object?>("result", TagWriteStatus.Refused.Name()));
        SparkplugLog.CommandRefused(_logger, device, count, reason);
    }

    /// <summary>A DCMD as it is carried out: its device and its metric writes, each metric once.</summary>
    internal sealed record DeviceCommand(SparkplugDevice Device, IReadOnlyList<MetricWrite> Writes);

    /// <summary>A metric to write, as the command named it, with the value of its last mention at <paramref name="Position"/>.</summary>
    internal sealed record MetricWrite(SparkplugMetric Metric, string Label, SparkplugCommandMetric Command, int Position);
}
