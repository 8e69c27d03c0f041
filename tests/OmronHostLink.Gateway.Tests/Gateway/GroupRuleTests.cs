using System.Globalization;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Tests.Mqtt;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// Every rule a poll group must follow — the HostLink section's own and those the outputs add (a name that is a topic
/// level or a metric name, a group that can be written) — sees the groups the gateway polls: a group whatever the form
/// of its interval, and a row of a tag file alike. Each bad group stops the start with one message naming its key.
/// </summary>
public sealed class GroupRuleTests : IDisposable
{
    private readonly string _directory = Directory.CreateTempSubdirectory("hostlink-group-rules-").FullName;

    public void Dispose() => Directory.Delete(_directory, recursive: true);

    /// <summary>A rule: the output it needs, a group that breaks it, and what its message says for a group and for a row.</summary>
    public sealed record Rule(string Output, string Name, string Address, string Type, int Count, bool Writable, string GroupMessage, string RowMessage);

    private static readonly Dictionary<string, Rule> Rules = new()
    {
        ["MQTT topic level"] = new("Mqtt", "lev+els", "D100", "int16", 1, false,
            ": the group's name is a topic level for MQTT and holds '+'", ": name 'lev+els' contains '+'"),
        ["Sparkplug metric name"] = new("Sparkplug", "lev#els", "D100", "int16", 1, false,
            ": the group's name is a Sparkplug metric name and it contains '#'", ": name 'lev#els' contains '#'"),
        ["writable completion flag"] = new("Mqtt", "flag", "T5", "bit", 1, true,
            ":Writable: T5 is a timer/counter completion flag, which the PLC sets itself; it cannot be written.",
            " (Writable): T5 is a timer/counter completion flag, which the PLC sets itself; it cannot be written."),
        ["writable bit group"] = new("Sparkplug", "bits", "CIO10.00", "bit", 4, true,
            ":Writable: a writable bit group must have Count 1 (one bit, written on its own); it has 4.",
            " (Writable): a writable bit group must have Count 1 (one bit, written on its own); it has 4."),
        ["completion flag of several"] = new("", "flags", "T5", "bit", 2, false,
            ":Count must be 1 for a timer/counter completion flag (T5); it is 2.",
            " (Count) must be 1 for a timer/counter completion flag (T5); it is 2."),
        ["beyond the area"] = new("", "far", "D9999", "int32", 1, false,
            ": 1 × int32 from D9999: ", ": 1 × int32 from D9999: "),
    };

    /// <summary>The forms a group takes: under Groups with each duration form of its interval, or a row of a tag file.</summary>
    private static readonly string[] Forms = ["00:00:01", "1s", "1000ms", "tag file"];

    public static TheoryData<string, string> Cases()
    {
        var data = new TheoryData<string, string>();
        foreach (string rule in Rules.Keys)
        {
            foreach (string form in Forms)
            {
                data.Add(rule, form);
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Cases))]
    public async Task Every_group_rule_sees_the_group_in_every_form_and_names_its_key_once(string ruleName, string form)
    {
        Rule rule = Rules[ruleName];
        (Dictionary<string, string?> config, string key) = Config(rule, form);
        using IHost host = MqttGatewayConfig.Build(config, new CapturingLoggerProvider());

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        error.Should().BeOfType<OptionsValidationException>("the group is refused at start ({0})", error);
        IReadOnlyList<string> failures = ((OptionsValidationException)error!).Failures.ToList();
        string message = key + (form == "tag file" ? rule.RowMessage : rule.GroupMessage);
        failures.Should().ContainSingle("one message for one bad group: {0}", string.Join(" | ", failures))
            .Which.Should().StartWith(message);
    }

    /// <summary>The cases the reliability trial found: each stops the gateway process with exit code 2 and one message.</summary>
    [Theory]
    [InlineData("MQTT topic level", "1s")]
    [InlineData("writable completion flag", "1s")]
    [InlineData("writable bit group", "1s")]
    [InlineData("MQTT topic level", "tag file")]
    [InlineData("writable completion flag", "tag file")]
    [InlineData("writable bit group", "tag file")]
    public async Task The_gateway_process_refuses_the_bad_group_with_one_message_naming_its_key(string ruleName, string form)
    {
        Rule rule = Rules[ruleName];
        (Dictionary<string, string?> config, string key) = Config(rule, form);
        var error = new StringWriter();
        string[] args = ["--contentRoot", _directory, .. config.Where(c => c.Value is not null).Select(c => $"--{c.Key}={c.Value}")];

        int exitCode = await GatewayProgram.RunAsync(args, error);

        string output = error.ToString();
        exitCode.Should().Be(2, output);
        string[] problems = output.Split('\n').Where(l => l.StartsWith("  - ", StringComparison.Ordinal)).ToArray();
        problems.Should().ContainSingle("one message: {0}", output)
            .Which.Should().StartWith("  - " + key + (form == "tag file" ? rule.RowMessage : rule.GroupMessage));
    }

    /// <summary>The configuration of a gateway whose only group breaks <paramref name="rule"/> in <paramref name="form"/>, and the key that names it.</summary>
    private (Dictionary<string, string?> Config, string Key) Config(Rule rule, string form)
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(9, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal) && !k.Key.Contains("StateDirectory", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        if (rule.Output == "Mqtt")
        {
            config["Mqtt:Host"] = "127.0.0.1";
            config["Mqtt:Port"] = "1";
            config["Mqtt:StateDirectory"] = MqttGatewayConfig.NewStateDirectory();
        }
        else if (rule.Output == "Sparkplug")
        {
            config["Sparkplug:Host"] = "127.0.0.1";
            config["Sparkplug:Port"] = "1";
            config["Sparkplug:GroupId"] = "Plant1";
            config["Sparkplug:EdgeNodeId"] = "gw1";
        }

        if (form != "tag file")
        {
            string g = $"HostLink:Links:plc:Groups:{rule.Name}:";
            config[g + "Address"] = rule.Address;
            config[g + "Type"] = rule.Type;
            config[g + "Count"] = rule.Count.ToString(CultureInfo.InvariantCulture);
            config[g + "Interval"] = form;
            config[g + "Writable"] = rule.Writable ? "true" : "false";
            return (config, $"HostLink:Links:plc:Groups:{rule.Name}");
        }

        string file = Path.Combine(_directory, Guid.NewGuid().ToString("N") + ".csv");
        File.WriteAllText(file, "name,address,type,writable,count\n"
            + $"{rule.Name},{rule.Address},{rule.Type},{(rule.Writable ? "true" : "false")},{rule.Count.ToString(CultureInfo.InvariantCulture)}\n");
        config["HostLink:Links:plc:TagFiles:0:Path"] = file;
        config["HostLink:Links:plc:TagFiles:0:Format"] = "Plain";
        return (config, $"HostLink:Links:plc:TagFiles:0:Path {file}, line 2: tag '{rule.Name}'");
    }
}
