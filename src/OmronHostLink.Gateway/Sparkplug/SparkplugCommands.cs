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
internal sealed class SparkplugCommands
{
    /// <summary>How many commands may wait; more are refused at once.</summary>
    public const int Backlog = 256;

    private readonly Channel<(string Device, byte[] Payload)> _commands = Channel.CreateBounded<(string, byte[])>(new BoundedChannelOptions(Backlog) { SingleReader = true });
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

    /// <summary>Takes a DCMD from the MQTT client's receive path; never blocks it.</summary>
    public void Accept(string device, byte[] payload)
    {
        if (!_commands.Writer.TryWrite((device, payload)))
        {
            Refused(device, "(all)", $"{Backlog} commands are already waiting; send it again later.");
        }
    }

    /// <summary>Carries out commands in the order they came until <paramref name="cancellationToken"/> is cancelled.</summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        try
        {
            await foreach ((string device, byte[] payload) in _commands.Reader.ReadAllAsync(cancellationToken).ConfigureAwait(false))
            {
                try
                {
                    await ExecuteAsync(device, payload, cancellationToken).ConfigureAwait(false);
                }
                catch (Exception e) when (e is not OperationCanceledException && e is not OutOfMemoryException)
                {
                    // A bug must not end the loop: every later command would be ignored.
                    Refused(device, "(all)", $"the gateway failed on the command ({e.GetType().Name}: {e.Message}).");
                }
            }
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            // Stopping.
        }
    }

    /// <summary>Checks and carries out the metrics of one DCMD, in their order.</summary>
    /// <returns>The outcome of each metric, by its name (or <c>alias N</c>).</returns>
    public async Task<IReadOnlyList<(string Metric, TagWriteOutcome Outcome)>> ExecuteAsync(string deviceId, byte[] payload, CancellationToken cancellationToken)
    {
        var outcomes = new List<(string, TagWriteOutcome)>();
        SparkplugDevice? device = _node.Device(deviceId);
        IReadOnlyList<SparkplugCommandMetric>? metrics = SparkplugCommandMetric.Parse(payload);
        if (device is null || metrics is null)
        {
            string why = device is null ? $"this edge node has no device {deviceId}." : "the payload is not a Sparkplug B payload.";
            outcomes.Add(("(all)", Refused(deviceId, "(all)", why)));
            return outcomes;
        }

        foreach (SparkplugCommandMetric command in metrics)
        {
            string label = command.Name ?? $"alias {command.Alias}";
            SparkplugMetric? metric = device.Metrics.FirstOrDefault(m => command.Name is { } n ? m.Name == n : m.Alias == command.Alias);
            TagWriteOutcome outcome;
            if (metric is null)
            {
                outcome = Refused(deviceId, label, $"device {deviceId} has no such metric.");
            }
            else if (!_enabled)
            {
                outcome = Refused(deviceId, label, "writes are disabled (Sparkplug:Writes:Enabled is false).");
            }
            else if (!command.TryGetValue(metric.DataType, out JsonElement value, out string error))
            {
                outcome = Refused(deviceId, label, $"{error} (the metric is {metric.DataType}).");
            }
            else
            {
                TagDefinition tag = device.Tags[metric.Tag];
                outcome = await _writer.WriteAsync(tag, value, metric.Element < 0 ? null : metric.Element, cancellationToken).ConfigureAwait(false);
                if (outcome.Status == TagWriteStatus.Refused)
                {
                    Refused(deviceId, label, outcome.Error!);
                }
                else if (outcome.IsDone)
                {
                    _writes.Add(1, new KeyValuePair<string, object?>("result", outcome.Status.Name()));
                    SparkplugLog.WriteDone(_logger, deviceId, label, tag.Address.ToString(), value.GetRawText());
                }
                else
                {
                    _writes.Add(1, new KeyValuePair<string, object?>("result", outcome.Status.Name()));
                    SparkplugLog.WriteFailed(_logger, deviceId, label, tag.Address.ToString(), value.GetRawText(), outcome.Error!);
                }
            }

            outcomes.Add((label, outcome));
        }

        return outcomes;
    }

    private TagWriteOutcome Refused(string device, string metric, string reason)
    {
        _writes.Add(1, new KeyValuePair<string, object?>("result", TagWriteStatus.Refused.Name()));
        SparkplugLog.WriteRefused(_logger, device, metric, reason);
        return TagWriteOutcome.Refused(reason);
    }
}
