namespace OmronHostLink.Tests.Settings;

/// <summary>The send interval through the one client settings type: read from configuration keys, checked, mapped.</summary>
public sealed class SendIntervalSettingTests
{
    private static HostLinkClientSettings Read(params (string Key, string Value)[] pairs)
    {
        var settings = new HostLinkClientSettings();
        settings.Read(pairs.Select(p => new KeyValuePair<string, string?>(p.Key, p.Value)).Append(new("Tcp:Host", "127.0.0.1")).Append(new("Tcp:Port", "9600")));
        return settings;
    }

    [Fact]
    public void A_send_interval_in_configuration_reaches_the_client_options()
    {
        HostLinkClientSettings settings = Read(("SendInterval", "50ms"));
        settings.Validate().Should().BeEmpty();
        settings.ToClientOptions().SendInterval.Should().Be(TimeSpan.FromMilliseconds(50));
    }

    [Fact]
    public void Unset_it_is_none()
        => Read().ToClientOptions().SendInterval.Should().Be(TimeSpan.Zero);

    [Fact]
    public void Beyond_10_s_it_is_refused_naming_the_key()
        => Read(("SendInterval", "11s")).Validate().Should().ContainSingle(p => p.Key == "SendInterval")
            .Which.Message.Should().Contain("0 to 10 s");
}
