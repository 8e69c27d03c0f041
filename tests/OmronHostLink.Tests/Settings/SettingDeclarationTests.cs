using System.ComponentModel;
using System.Reflection;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Settings;

/// <summary>
/// Every client setting is declared once (key, reader, rule, default, how it applies to the options), and everything
/// settable about a client is either a declared setting or on an explicit list of what only code can set.
/// </summary>
public sealed class SettingDeclarationTests
{
    /// <summary>What only code sets: objects and clocks configuration cannot hold, or values the settings derive.</summary>
    private static readonly string[] CodeOnlyOptions =
    [
        nameof(HostLinkClientOptions.LineTiming), // derived from the Serial section's speed and format
        nameof(HostLinkClientOptions.LoggerFactory),
        nameof(HostLinkClientOptions.MeterFactory),
        nameof(HostLinkClientOptions.LinkName), // the host's name for the link (DI: the client's name)
        nameof(HostLinkClientOptions.TimeProvider),
    ];

    private static readonly string[] CodeOnlyLineSettings = [];

    private static HostLinkClientSettings Read(params (string Key, string Value)[] pairs)
    {
        var settings = new HostLinkClientSettings();
        settings.Read(pairs.Select(p => new KeyValuePair<string, string?>(p.Key, p.Value)).Append(new("Tcp", "127.0.0.1:9600")));
        return settings;
    }

    private static string[] Settable(Type type)
        => type.GetProperties(BindingFlags.Public | BindingFlags.Instance).Where(p => p.SetMethod?.IsPublic == true).Select(p => p.Name).ToArray();

    [Fact]
    public void Every_public_settable_option_is_a_declared_setting_or_code_only()
    {
        string[] declared = HostLinkClientSettings.Declared.Select(s => s.Key).ToArray();
        Settable(typeof(HostLinkClientOptions)).Except(declared).Except(CodeOnlyOptions)
            .Should().BeEmpty("a client option is a declared setting of HostLinkClientSettings, or listed here as code-only");
        declared.Intersect(CodeOnlyOptions).Should().BeEmpty();
        declared.Except(Settable(typeof(HostLinkClientOptions))).Should().BeEmpty("each declared setting applies to the option of its name");
        declared.Except(Settable(typeof(HostLinkClientSettings))).Should().BeEmpty("each declared setting is a property of the settings type");
        Settable(typeof(HostLinkClientSettings)).Except(declared).Should().BeEquivalentTo(["Serial", "Tcp"]);
    }

    [Fact]
    public void Every_public_settable_line_setting_is_a_declared_serial_setting()
    {
        string[] declared = HostLinkSerialSettings.Declared.Select(s => s.Key).ToArray();
        Settable(typeof(SerialLineSettings)).Except(declared).Except(CodeOnlyLineSettings).Should().BeEmpty();
        declared.Should().BeEquivalentTo(Settable(typeof(HostLinkSerialSettings)));
    }

    [Fact]
    public void Unset_settings_give_the_options_defaults()
    {
        HostLinkClientOptions mapped = Read().ToClientOptions();
        var fresh = new HostLinkClientOptions();
        foreach (string key in HostLinkClientSettings.Declared.Select(s => s.Key))
        {
            PropertyInfo property = typeof(HostLinkClientOptions).GetProperty(key)!;
            object? value = property.GetValue(mapped);
            object? expected = property.GetValue(fresh);
            if (value is IDictionary<int, TimeSpan> map)
            {
                map.Should().BeEquivalentTo((IDictionary<int, TimeSpan>)expected!, key);
            }
            else
            {
                value.Should().Be(expected, key);
            }
        }
    }

    [Fact]
    public void Compound_reads_and_unit_send_intervals_reach_the_options_from_configuration()
    {
        HostLinkClientSettings settings = Read(("UseCompoundRead", "true"), ("UnitSendIntervals:3", "200ms"), ("UnitSendIntervals:7", "1s"));
        settings.Validate().Should().BeEmpty();
        HostLinkClientOptions options = settings.ToClientOptions();
        options.UseCompoundRead.Should().Be(CompoundReadMode.On);
        options.UnitSendIntervals.Should().BeEquivalentTo(new Dictionary<int, TimeSpan> { [3] = TimeSpan.FromMilliseconds(200), [7] = TimeSpan.FromSeconds(1) });
    }

    [Fact]
    public void A_unit_send_interval_that_cannot_be_used_is_a_problem_at_its_key()
    {
        Read(("UnitSendIntervals:x", "1s")).Validate().Should().ContainSingle()
            .Which.ToString().Should().Be("UnitSendIntervals:x: 'x' is not a unit number (0-31)");
        Read(("UnitSendIntervals:40", "1s")).Validate().Should().ContainSingle()
            .Which.ToString().Should().Be("UnitSendIntervals: names unit 40: 40 is not a unit number (0-31)");
        Read(("UnitSendIntervals:3", "11s")).Validate().Should().ContainSingle()
            .Which.ToString().Should().StartWith("UnitSendIntervals: gives unit 3 11000 ms is not 0 to 10 s");
    }

    [Fact]
    public void A_renamed_key_says_what_it_is_now_called()
        => Read(("Protocol", "Fins")).Validate().Should().ContainSingle()
            .Which.ToString().Should().Be("Protocol: is now called CommandSet; rename the key");

    [Fact]
    public void The_components_defaults_are_the_declared_ones()
    {
        var plc = new HostLinkPlc();
        var client = new HostLinkClientOptions();
        var line = new SerialLineSettings();
        plc.BaudRate.Should().Be(line.BaudRate);
        plc.DataBits.Should().Be(line.DataBits);
        plc.Parity.Should().Be(line.Parity);
        plc.StopBits.Should().Be(line.StopBits);
        plc.UnitNumber.Should().Be(client.UnitNumber);
        plc.CommandSet.Should().Be(client.CommandSet);
        plc.TurnaroundAllowance.Should().Be(client.TurnaroundAllowance);
        plc.ReadRetries.Should().Be(client.ReadRetries);
        plc.AllowReadModifyWriteBits.Should().Be(client.AllowReadModifyWriteBits);

        // The designer's [DefaultValue] attributes are constants: each must say what the property starts with.
        foreach (PropertyInfo property in typeof(HostLinkPlc).GetProperties())
        {
            if (property.GetCustomAttribute<DefaultValueAttribute>() is { } attribute)
            {
                property.GetValue(plc).Should().Be(attribute.Value, property.Name);
            }
        }
    }
}
