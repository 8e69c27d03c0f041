namespace OmronHostLink.Tests.Settings;

/// <summary>UseCompoundRead through the one client settings type: read from configuration keys, checked, mapped.</summary>
public sealed class CompoundReadSettingTests
{
    private static HostLinkClientSettings Read(params (string Key, string Value)[] pairs)
    {
        var settings = new HostLinkClientSettings();
        settings.Read(pairs.Select(p => new KeyValuePair<string, string?>(p.Key, p.Value)).Append(new("Tcp:Host", "127.0.0.1")).Append(new("Tcp:Port", "9600")));
        return settings;
    }

    [Theory]
    [InlineData("Auto", CompoundReadMode.Auto)]
    [InlineData("on", CompoundReadMode.On)]
    [InlineData("OFF", CompoundReadMode.Off)]
    [InlineData("true", CompoundReadMode.On)]
    [InlineData("false", CompoundReadMode.Off)]
    public void The_key_reaches_the_client_options(string value, CompoundReadMode expected)
    {
        HostLinkClientSettings settings = Read(("UseCompoundRead", value));
        settings.Validate().Should().BeEmpty();
        settings.ToClientOptions().UseCompoundRead.Should().Be(expected);
    }

    [Fact]
    public void Unset_it_is_Auto()
        => Read().ToClientOptions().UseCompoundRead.Should().Be(CompoundReadMode.Auto);

    [Fact]
    public void Another_value_is_refused_naming_the_key_and_the_choices()
        => Read(("UseCompoundRead", "sometimes")).Validate().Should().ContainSingle(p => p.Key == "UseCompoundRead")
            .Which.Message.Should().Be("'sometimes' is not one of Auto, On, Off, true, false");
}
