using System.Diagnostics;
using System.Globalization;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>Configuration and hosts for worker tests with MQTT: one link "plc" to the simulator, topics under "test".</summary>
public static class MqttGatewayConfig
{
    /// <summary>The topic prefix the tests use.</summary>
    public const string Prefix = "test";

    /// <summary>A worker polling the simulator at <paramref name="plcPort"/> and publishing to <paramref name="broker"/> (fast timings).</summary>
    public static Dictionary<string, string?> Create(int plcPort, MosquittoBroker? broker, string clientId = "worker-test") => new()
    {
        ["HostLink:Links:plc:Tcp"] = $"127.0.0.1:{plcPort}",
        ["HostLink:Links:plc:Serial:BaudRate"] = "115200",
        ["HostLink:Links:plc:TurnaroundAllowance"] = Allowances.LosslessLineText,
        ["HostLink:Links:plc:ReadRetries"] = "1",
        ["HostLink:Links:plc:Tcp:ConnectTimeout"] = "00:00:00.500",
        ["HostLink:Links:plc:Backoff:Initial"] = "00:00:00.100",
        ["HostLink:Links:plc:Backoff:Max"] = "00:00:00.200",
        ["Mqtt:Host"] = "127.0.0.1",
        ["Mqtt:Port"] = (broker?.Port ?? 1).ToString(CultureInfo.InvariantCulture),
        ["Mqtt:ClientId"] = clientId,
        ["Mqtt:TopicPrefix"] = Prefix,
        ["Mqtt:Timeout"] = "00:00:05",
        ["Mqtt:Reconnect:Initial"] = "00:00:00.100",
        ["Mqtt:Reconnect:Max"] = "00:00:00.500",
        ["Mqtt:StateDirectory"] = NewStateDirectory(),
    };

    /// <summary>
    /// A state directory of its own for each gateway a test starts: the count of unsent messages one test leaves must not
    /// be announced in the next one. All are deleted when the test process ends.
    /// </summary>
    public static string NewStateDirectory() => Directory.CreateDirectory(Path.Combine(StateRoot.Path, Guid.NewGuid().ToString("N"))).FullName;

    /// <summary>Adds a poll group (a tag) to the link "plc".</summary>
    public static void Group(Dictionary<string, string?> config, string name, string address, string type = "int16", int count = 1, int intervalMs = 20, bool writable = false, int unit = 0)
    {
        string g = $"HostLink:Links:plc:Groups:{name}:";
        config[g + "Address"] = address;
        config[g + "Type"] = type;
        config[g + "Count"] = count.ToString(CultureInfo.InvariantCulture);
        config[g + "Interval"] = TimeSpan.FromMilliseconds(intervalMs).ToString();
        config[g + "Log"] = "OnChange";
        config[g + "Unit"] = unit.ToString(CultureInfo.InvariantCulture);
        if (writable)
        {
            config[g + "Writable"] = "true";
        }
    }

    /// <summary>The value topic of a tag on the link "plc".</summary>
    public static string Topic(string tag, int unit = 0) => $"{Prefix}/plc/{unit}/{tag}";

    /// <summary>Builds the worker's host as Program.cs does, from in-memory configuration, logging to <paramref name="logs"/>; <paramref name="services"/> may add to it.</summary>
    public static IHost Build(Dictionary<string, string?> config, CapturingLoggerProvider logs, Action<IServiceCollection>? services = null)
        => TestGatewayHost.Build(config, logs, TimeSpan.FromSeconds(10), services);

    /// <summary>Waits until <paramref name="condition"/> holds (the shared wait, looking again at each new log entry).</summary>
    public static Task Eventually(Func<bool> condition, string what, CapturingLoggerProvider logs, TimeSpan? patience = null)
        => OmronHostLink.Testing.Eventually.UntilAsync(condition, what, logs, patience);

    private static class StateRoot
    {
        public static readonly string Path = Create();

        private static string Create()
        {
            string path = Directory.CreateTempSubdirectory("ohl-gateway-state-").FullName;
            AppDomain.CurrentDomain.ProcessExit += (_, _) =>
            {
                try
                {
                    Directory.Delete(path, recursive: true);
                }
                catch (IOException)
                {
                }
            };
            return path;
        }
    }
}
