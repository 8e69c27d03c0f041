using System.Net;
using System.Net.Sockets;
using System.Reflection;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Tests.Telemetry;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// Every configuration mistake, in every section, ends the start with exit code 2 and one message naming the key (or
/// the file and line), and no stack trace — read from a real appsettings.json and the command line, as in production.
/// </summary>
public sealed class GatewayStartupTests
{
    /// <summary>A valid configuration: one link to a closed loopback port, MQTT to another.</summary>
    private const string ValidJson = """
        {
          "Logging": { "LogLevel": { "Default": "Warning" } },
          "HostLink": {
            "Links": {
              "plc": {
                "Tcp": "127.0.0.1:9",
                "Groups": {
                  "levels": { "Address": "D100", "Type": "int16" }
                }
              }
            }
          },
          "Mqtt": { "Host": "127.0.0.1", "Port": 1, "TopicPrefix": "test" }
        }
        """;

    public static TheoryData<string, string, string> Mistakes()
    {
        var data = new TheoryData<string, string, string>
        {
            // case, change (JSON text replacement "old=>new", or command-line "--key=value"), what the message says
            { "JSON syntax error", "\"Type\": \"int16\" }=>\"Type\" \"int16\" }", "appsettings.json, line 8, column 49: '\"' is invalid after a property name" },
            { "JSON duplicate key", "\"Type\": \"int16\" }=>\"Type\": \"int16\" },\n \"levels\": { \"Address\": \"D5\" }", "appsettings.json, line 9: duplicate key 'HostLink:Links:plc:Groups:levels:Address', given on line 8 already" },
            { "JSON duplicate key in another case", "\"Type\": \"int16\" }=>\"Type\": \"int16\" },\n \"Levels\": { \"Address\": \"D5\" }", "appsettings.json, line 9: duplicate key 'HostLink:Links:plc:Groups:Levels:Address', given on line 8 already" },
            { "misspelt section", "\"Mqtt\":=>\"Mqt\":", "Mqt is not a section the gateway reads; did you mean Mqtt?" },
            { "misspelt section on the command line", "--Mqt:Host=127.0.0.1", "Mqt is not a section the gateway reads; did you mean Mqtt?" },
            { "unknown section", "\"Mqtt\":=>\"Extra\": {}, \"Mqtt\":", "Extra is not a section the gateway reads" },
            { "misspelt Mqtt key", "--Mqtt:QueueCapacty=5", "Mqtt:QueueCapacty is not a setting here" },
            { "misspelt Mqtt key", "--Mqtt:TopicPrefx=plant", "Mqtt:TopicPrefx is not a setting here" },
            { "wrong type", "--Mqtt:Port=abc", "Mqtt:Port 'abc' is not a whole number" },
            { "wrong type", "--Mqtt:Writes:Enabled=yes", "Mqtt:Writes:Enabled 'yes' is not true or false" },
            { "wrong type", "--Mqtt:Timeout=10", "Mqtt:Timeout '10' has no unit" },
            { "out of range", "--Mqtt:Port=70000", "Mqtt:Port must be 1-65535; it is 70000" },
            { "out of range", "--Mqtt:QueueCapacity=0", "Mqtt:QueueCapacity must be 1-10000000" },
            { "keep-alive 0", "--Mqtt:KeepAlive=0s", "Mqtt:KeepAlive must be 1s to 18:12:15" },
            { "keep-alive 0 as a time span", "--Mqtt:KeepAlive=00:00:00", "Mqtt:KeepAlive must be 1s to 18:12:15" },
            { "TLS server name not a host", "--Mqtt:Tls:Enabled=true --Mqtt:Tls:ServerName=broker.plant.local:8883", "Mqtt:Tls:ServerName 'broker.plant.local:8883' is not a host name or address" },
            { "OTLP endpoint not a URL", "--OpenTelemetry:Exporter=Otlp --OTEL_EXPORTER_OTLP_ENDPOINT=collector:4317", "OTEL_EXPORTER_OTLP_ENDPOINT 'collector:4317' is not an http:// or https:// URL" },
            { "OTLP endpoint host not an IPv4 address", "--OpenTelemetry:Exporter=Otlp --OTEL_EXPORTER_OTLP_ENDPOINT=http://127.0.0.1.5:4317", "OTEL_EXPORTER_OTLP_ENDPOINT 'http://127.0.0.1.5:4317': '127.0.0.1.5' is not a host name or address: it looks like an IPv4 address" },
            { "durable queue size out of range", "--Mqtt:DurableQueue:MaxMegabytes=0", "Mqtt:DurableQueue:MaxMegabytes must be 1-1048576" },
            { "durable queue age 0", "--Mqtt:DurableQueue:MaxAge=0s", "Mqtt:DurableQueue:MaxAge must be at least 1s" },
            { "durable queue age without a unit", "--Mqtt:DurableQueue:MaxAge=7", "Mqtt:DurableQueue:MaxAge '7' has no unit" },
            { "durable queue where nothing can be written", "--Mqtt:DurableQueue:Enabled=true --Mqtt:StateDirectory=appsettings.json/state", "Mqtt:DurableQueue:Enabled: the queue's database" },
            { "link host as a URL", "--HostLink:Links:plc:Tcp=tcp://127.0.0.1:27600", "HostLink:Links:plc:Tcp: 'tcp://127.0.0.1:27600'" },
            { "link host not an IPv4 address", "--HostLink:Links:plc:Tcp=127.0.0.1.5:27600", "HostLink:Links:plc:Tcp '127.0.0.1.5' does not name a host: it looks like an IPv4 address" },
            { "broker host not an IPv4 address", "--Mqtt:Host=127.0.0.1.5", "Mqtt:Host '127.0.0.1.5' is not a host name or address: it looks like an IPv4 address" },
            { "broker host as a URL", "--Mqtt:Host=mqtt://127.0.0.1", "Mqtt:Host 'mqtt://127.0.0.1' is not a host name or address" },
            { "misspelt log level", "--Logging:LogLevel:Default=Informaton", "Logging:LogLevel:Default 'Informaton' is not a log level" },
            { "misspelt log level of a provider", "--Logging:Console:LogLevel:OmronHostLink=Verbose", "Logging:Console:LogLevel:OmronHostLink 'Verbose' is not a log level" },
            { "misspelt key of a disabled Mqtt section", "--Mqtt:Enabled=false --Mqtt:TopicPrefx=plant", "Mqtt:TopicPrefx is not a setting here" },
            { "wrong type in a disabled Mqtt section", "--Mqtt:Enabled=false --Mqtt:Port=abc", "Mqtt:Port 'abc' is not a whole number" },
            { "misspelt key of a disabled Sparkplug section", "--Sparkplug:Enabled=false --Sparkplug:EdgeNodId=line1", "Sparkplug:EdgeNodId is not a setting here" },
            { "misspelt telemetry key", "--OpenTelemetry:Exportr=Console", "OpenTelemetry:Exportr is not a setting here" },
            { "HostLink and Mqtt together", "--HostLink:Links:plc:Groups:levels:Intervall=1s --Mqtt:Port=abc", "HostLink:Links:plc:Groups:levels:Intervall is not a setting|Mqtt:Port 'abc' is not a whole number" },
        };

        // A typo in every key of the Mqtt section (nested ones included) is named.
        foreach (string key in Keys(typeof(MqttOptions), "Mqtt"))
        {
            string leaf = key.Substring(key.LastIndexOf(':') + 1);
            string typo = key.Substring(0, key.Length - leaf.Length) + leaf.Remove(1, 1);
            data.Add("typo in " + key, $"--{typo}=1", $"{typo} is not a setting here");
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Mistakes))]
    public async Task A_mistake_exits_2_with_one_message_naming_it_and_no_stack_trace(string mistake, string change, string expected)
    {
        string dir = Directory.CreateTempSubdirectory("hostlink-gateway-").FullName;
        try
        {
            string json = ValidJson;
            var args = new List<string> { "--contentRoot", dir };
            foreach (string part in change.Split(" --"))
            {
                if (part.StartsWith("--", StringComparison.Ordinal) || !part.Contains("=>", StringComparison.Ordinal))
                {
                    args.Add(part.StartsWith("--", StringComparison.Ordinal) ? part : "--" + part);
                }
                else
                {
                    string[] edit = part.Split("=>");
                    json.Should().Contain(edit[0], "the case edits the valid file");
                    json = json.Replace(edit[0], edit[1], StringComparison.Ordinal);
                }
            }

            await File.WriteAllTextAsync(Path.Combine(dir, "appsettings.json"), json);
            var error = new StringWriter();

            Task<int> run = GatewayProgram.RunAsync(args.ToArray(), error);
            await Eventually.UntilAsync(() => run.IsCompleted, $"{mistake} stops the start", patience: TimeSpan.FromSeconds(30));

            string output = error.ToString();
            (await run).Should().Be(2, output);
            output.Split("the configuration is not valid").Should().HaveCount(2, "one message: {0}", output);
            foreach (string fragment in expected.Split('|'))
            {
                output.Should().Contain(fragment, "the message names the mistake ({0})", mistake);
            }

            output.Should().NotMatchRegex(@"(?m)^\s+at ", "no stack trace: {0}", output);
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }

    [Fact]
    public async Task A_simulator_port_in_use_is_one_line_and_exit_code_2()
    {
        using var taken = new TcpListener(IPAddress.Loopback, 0);
        taken.Start();
        int port = ((IPEndPoint)taken.LocalEndpoint).Port;
        await using GatewayProcess process = GatewayProcess.Start(
        [
            "--Simulator:Enabled=true",
            $"--Simulator:Port={port}",
            $"--HostLink:Links:plc:Tcp=127.0.0.1:{port}",
            "--HostLink:Links:plc:Groups:g:Address=D0",
            "--Logging:LogLevel:Default=Warning",
        ]);
        if (await process.WaitForExitAsync(TimeSpan.FromSeconds(30)) is null)
        {
            await process.KillAsync();
        }

        string output = process.Output;
        process.ExitCode.Should().Be(2, output);
        output.Should().Contain($"Simulator:Port {port} on 127.0.0.1 is in use by another program");
        output.Split('\n').Where(l => l.Contains("in use", StringComparison.Ordinal)).Should().ContainSingle("one line says it: {0}", output);
        output.Should().NotMatchRegex(@"(?m)^\s+at ", "no stack trace: {0}", output).And.NotContain("Exception");
    }

    /// <summary>The configuration keys of an options class, nested sections included.</summary>
    private static IEnumerable<string> Keys(Type type, string path)
    {
        foreach (PropertyInfo p in type.GetProperties(BindingFlags.Public | BindingFlags.Instance).Where(p => p.SetMethod is { IsPublic: true }))
        {
            Type t = Nullable.GetUnderlyingType(p.PropertyType) ?? p.PropertyType;
            if (t.IsClass && t != typeof(string) && !t.IsGenericType)
            {
                foreach (string nested in Keys(t, $"{path}:{p.Name}"))
                {
                    yield return nested;
                }
            }
            else
            {
                yield return $"{path}:{p.Name}";
            }
        }
    }
}
