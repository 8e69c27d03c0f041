using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Settings;

/// <summary>Every setting reaches the library's option types; unset ones keep the library's defaults.</summary>
public sealed class HostLinkClientSettingsMappingTests
{
    [Fact]
    public void Every_setting_reaches_the_library()
    {
        var settings = new HostLinkClientSettings
        {
            Serial = new HostLinkSerialSettings
            {
                PortName = "/dev/ttyS4",
                BaudRate = 19200,
                DataBits = 8,
                Parity = SerialParity.Odd,
                StopBits = SerialStopBits.One,
                Handshake = SerialHandshake.XOnXOff,
                DtrEnable = true,
                RtsEnable = true,
            },
            UnitNumber = 7,
            CommandSet = HostLinkCommandSet.Fins,
            TurnaroundAllowance = TimeSpan.FromMilliseconds(750),
            ReadRetries = 5,
            WriteRetries = 1,
            WordOrder = WordOrder.HighWordFirst,
            LocalEcho = true,
            FinsResponseWait = 3,
            AllowReadModifyWriteBits = true,
            Model = "CPM1A",
        };

        HostLinkClientOptions options = settings.ToClientOptions();
        options.Model.Should().Be("CPM1A");
        options.UnitNumber.Should().Be(7);
        options.CommandSet.Should().Be(HostLinkCommandSet.Fins);
        options.TurnaroundAllowance.Should().Be(TimeSpan.FromMilliseconds(750));
        options.ReadRetries.Should().Be(5);
        options.WriteRetries.Should().Be(1);
        options.WordOrder.Should().Be(WordOrder.HighWordFirst);
        options.LocalEcho.Should().BeTrue();
        options.FinsResponseWait.Should().Be(3);
        options.AllowReadModifyWriteBits.Should().BeTrue();
        options.LineTiming.BaudRate.Should().Be(19200);
        options.LineTiming.BitsPerCharacter.Should().Be(11, "8O1 is 1 start + 8 data + 1 parity + 1 stop bit");

        SerialLineSettings line = settings.Serial.ToLineSettings();
        line.PortName.Should().Be("/dev/ttyS4");
        line.BaudRate.Should().Be(19200);
        line.DataBits.Should().Be(8);
        line.Parity.Should().Be(SerialParity.Odd);
        line.StopBits.Should().Be(SerialStopBits.One);
        line.Handshake.Should().Be(SerialHandshake.XOnXOff);
        line.DtrEnable.Should().BeTrue();
        line.RtsEnable.Should().BeTrue();
    }

    [Fact]
    public void Unset_settings_keep_the_library_defaults()
    {
        var settings = new HostLinkClientSettings();
        settings.Tcp.Host = "127.0.0.1";
        settings.Tcp.Port = 9;

        settings.ToClientOptions().Should().BeEquivalentTo(new HostLinkClientOptions(), o => o.Excluding(x => x.LineTiming));
        settings.ToClientOptions().LineTiming.Should().BeEquivalentTo(OmronHostLink.Transports.LineTiming.Default);
        settings.Serial.ToLineSettings().Should().BeEquivalentTo(new SerialLineSettings());
    }
}
