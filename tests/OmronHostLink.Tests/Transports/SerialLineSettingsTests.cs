using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Transports;

public sealed class SerialLineSettingsTests
{
    private static SerialLineSettings Valid() => new() { PortName = "/dev/ttyUSB0" };

    [Fact]
    public void Defaults_are_the_Omron_Host_Link_defaults()
    {
        var settings = new SerialLineSettings();

        settings.PortName.Should().BeEmpty();
        settings.BaudRate.Should().Be(9600);
        settings.DataBits.Should().Be(7);
        settings.Parity.Should().Be(SerialParity.Even);
        settings.StopBits.Should().Be(SerialStopBits.Two);
        settings.Handshake.Should().Be(SerialHandshake.None);
        settings.DtrEnable.Should().BeFalse();
        settings.RtsEnable.Should().BeFalse();
        settings.ToString().Should().Be(" 9600 7E2");
    }

    [Theory]
    [InlineData(7, SerialParity.Even, SerialStopBits.Two, 11)]
    [InlineData(7, SerialParity.None, SerialStopBits.One, 9)]
    [InlineData(8, SerialParity.None, SerialStopBits.One, 10)]
    [InlineData(8, SerialParity.Odd, SerialStopBits.One, 11)]
    [InlineData(8, SerialParity.Even, SerialStopBits.Two, 12)]
    public void BitsPerCharacter_counts_start_data_parity_and_stop_bits(int dataBits, SerialParity parity, SerialStopBits stopBits, int expected)
    {
        var settings = new SerialLineSettings { DataBits = dataBits, Parity = parity, StopBits = stopBits };
        settings.BitsPerCharacter.Should().Be(expected);
    }

    [Fact]
    public void CharacterTime_at_9600_7E2_is_11_bits_over_9600_baud()
    {
        TimeSpan time = new SerialLineSettings().CharacterTime;

        time.TotalSeconds.Should().BeApproximately(11.0 / 9600, 1e-7);
        time.Should().BeGreaterThanOrEqualTo(TimeSpan.FromTicks(11 * TimeSpan.TicksPerSecond / 9600), "it rounds up, never down");
    }

    [Fact]
    public void CharacterTime_at_115200_8N1_is_10_bits_over_115200_baud()
    {
        var settings = new SerialLineSettings { BaudRate = 115200, DataBits = 8, Parity = SerialParity.None, StopBits = SerialStopBits.One };
        settings.CharacterTime.TotalSeconds.Should().BeApproximately(10.0 / 115200, 1e-7);
    }

    [Theory]
    [InlineData(300)]
    [InlineData(1200)]
    [InlineData(9600)]
    [InlineData(19200)]
    [InlineData(38400)]
    [InlineData(115200)]
    [InlineData(230400)]
    public void Validate_accepts_standard_baud_rates(int baudRate)
    {
        var settings = Valid();
        settings.BaudRate = baudRate;
        settings.Invoking(s => s.Validate()).Should().NotThrow();
    }

    [Theory]
    [InlineData(7, SerialParity.None, SerialStopBits.One)]
    [InlineData(7, SerialParity.Even, SerialStopBits.Two)]
    [InlineData(7, SerialParity.Odd, SerialStopBits.One)]
    [InlineData(8, SerialParity.None, SerialStopBits.One)]
    [InlineData(8, SerialParity.Even, SerialStopBits.One)]
    public void Validate_accepts_every_frame_format(int dataBits, SerialParity parity, SerialStopBits stopBits)
    {
        var settings = Valid();
        settings.DataBits = dataBits;
        settings.Parity = parity;
        settings.StopBits = stopBits;
        settings.Invoking(s => s.Validate()).Should().NotThrow();
    }

    [Theory]
    [InlineData("")]
    [InlineData("   ")]
    [InlineData("COM1\0")]
    public void Validate_rejects_a_bad_port_name(string portName)
    {
        var settings = Valid();
        settings.PortName = portName;
        settings.Invoking(s => s.Validate()).Should().Throw<ArgumentException>()
            .Where(e => e.ParamName == "PortName").WithMessage("*PortName*");
    }

    [Theory]
    [InlineData(0)]
    [InlineData(-9600)]
    [InlineData(100)]
    [InlineData(14400)]
    [InlineData(460800)]
    public void Validate_rejects_a_non_standard_baud_rate(int baudRate)
    {
        var settings = Valid();
        settings.BaudRate = baudRate;
        settings.Invoking(s => s.Validate()).Should().Throw<ArgumentException>()
            .Where(e => e.ParamName == "BaudRate").WithMessage($"*BaudRate {baudRate}*9600*");
    }

    [Theory]
    [InlineData(5)]
    [InlineData(6)]
    [InlineData(9)]
    public void Validate_rejects_data_bits_other_than_7_or_8(int dataBits)
    {
        var settings = Valid();
        settings.DataBits = dataBits;
        settings.Invoking(s => s.Validate()).Should().Throw<ArgumentException>()
            .Where(e => e.ParamName == "DataBits").WithMessage($"*DataBits {dataBits} is not 7 or 8*");
    }

    [Fact]
    public void Validate_rejects_undefined_enum_values_naming_the_field()
    {
        var settings = Valid();
        settings.Parity = (SerialParity)9;
        settings.Invoking(s => s.Validate()).Should().Throw<ArgumentException>().Where(e => e.ParamName == "Parity").WithMessage("*Parity*");

        settings = Valid();
        settings.StopBits = (SerialStopBits)0;
        settings.Invoking(s => s.Validate()).Should().Throw<ArgumentException>().Where(e => e.ParamName == "StopBits").WithMessage("*StopBits*");

        settings = Valid();
        settings.Handshake = (SerialHandshake)7;
        settings.Invoking(s => s.Validate()).Should().Throw<ArgumentException>().Where(e => e.ParamName == "Handshake").WithMessage("*Handshake*");
    }

    [Fact]
    public void Validate_rejects_RtsEnable_with_hardware_handshake()
    {
        var settings = Valid();
        settings.Handshake = SerialHandshake.RequestToSend;
        settings.RtsEnable = true;
        settings.Invoking(s => s.Validate()).Should().Throw<ArgumentException>()
            .Where(e => e.ParamName == "RtsEnable").WithMessage("*RtsEnable*RequestToSend*");
    }

    [Fact]
    public void ToString_uses_the_short_form()
    {
        var settings = Valid();
        settings.ToString().Should().Be("/dev/ttyUSB0 9600 7E2");
        settings.Handshake = SerialHandshake.XOnXOff;
        settings.Parity = SerialParity.Odd;
        settings.StopBits = SerialStopBits.One;
        settings.ToString().Should().Be("/dev/ttyUSB0 9600 7O1 XON/XOFF");
    }
}
