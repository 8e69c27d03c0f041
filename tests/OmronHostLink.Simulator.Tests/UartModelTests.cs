using System.Text;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Simulator.Tests;

/// <summary>
/// The UART model behind the emulated line: what a receiver takes from a transmitter at other settings. The expected
/// characters are worked out by hand from the bit patterns (start bit, 7 or 8 data bits least significant first, parity,
/// stop bits), not by the model.
/// </summary>
public sealed class UartModelTests
{
    private static readonly byte[] Frame = Encoding.ASCII.GetBytes(GoldenFrames.Frames("c_mm")[0]);

    [Theory]
    [InlineData(9600, "7E2")]
    [InlineData(19200, "8N1")]
    [InlineData(4800, "7E1")]
    [InlineData(115200, "7O2")]
    [InlineData(1200, "8E1")]
    public void Matching_settings_deliver_the_bytes_unchanged(int baud, string format)
    {
        SerialLineSettings s = Settings(baud, format);

        List<UartModel.Received> received = UartModel.Transfer(Frame, s, s);

        received.Select(r => r.Value).Should().Equal(Frame);
        received.Should().OnlyContain(r => !r.Error);
    }

    [Theory]
    [InlineData("7E2", "7E1")]
    [InlineData("7E1", "7E2")]
    [InlineData("8N1", "8N2")]
    [InlineData("8N2", "8N1")]
    public void A_receiver_cannot_tell_one_stop_bit_from_two(string transmitter, string receiver)
    {
        List<UartModel.Received> received = UartModel.Transfer(Frame, Settings(9600, transmitter), Settings(9600, receiver));

        received.Select(r => r.Value).Should().Equal(Frame);
        received.Should().OnlyContain(r => !r.Error);
    }

    [Fact]
    public void Eight_bits_without_parity_read_at_7E2_give_parity_errors_where_the_bit_count_is_odd()
    {
        // '@' is 0x40: one 1 among its 7 data bits, so even parity wants a 1 where 8N1 sends data bit 7, a 0.
        // '0' is 0x30: two 1s, even parity wants the 0 that comes. 'M' is 0x4D: four 1s, parity 0 is right.
        List<UartModel.Received> received = UartModel.Transfer("@0M"u8, Settings(9600, "8N1"), Settings(9600, "7E2"));

        received.Select(r => r.Value).Should().Equal((byte)'@', (byte)'0', (byte)'M');
        received.Select(r => r.ParityError).Should().Equal(true, false, false);
        received.Should().OnlyContain(r => !r.FramingError);
    }

    [Fact]
    public void Seven_bits_with_even_parity_read_at_8N1_set_bit_7_where_the_parity_bit_is_1()
    {
        // The parity bit arrives where 8N1 expects data bit 7: '@' (parity 1) reads 0xC0, '0' (parity 0) reads 0x30.
        List<UartModel.Received> received = UartModel.Transfer("@0"u8, Settings(9600, "7E2"), Settings(9600, "8N1"));

        received.Select(r => r.Value).Should().Equal(0xC0, 0x30);
        received.Should().OnlyContain(r => !r.Error);
    }

    [Fact]
    public void Odd_parity_read_as_even_is_a_parity_error_on_every_character()
    {
        List<UartModel.Received> received = UartModel.Transfer(Frame, Settings(9600, "7O2"), Settings(9600, "7E2"));

        received.Select(r => r.Value).Should().Equal(Frame);
        received.Should().OnlyContain(r => r.ParityError);
    }

    [Theory]
    [InlineData(9600, 19200)]
    [InlineData(19200, 9600)]
    [InlineData(4800, 115200)]
    public void Another_speed_gives_garbage_with_errors(int transmitter, int receiver)
    {
        List<UartModel.Received> received = UartModel.Transfer(Frame, Settings(transmitter, "7E2"), Settings(receiver, "7E2"));

        received.Select(r => r.Value).Should().NotEqual(Frame);
        received.Should().Contain(r => r.Error);
    }

    internal static SerialLineSettings Settings(int baud, string format) => new()
    {
        PortName = "emulated",
        BaudRate = baud,
        DataBits = format[0] - '0',
        Parity = format[1] switch { 'E' => SerialParity.Even, 'O' => SerialParity.Odd, _ => SerialParity.None },
        StopBits = format[2] == '1' ? SerialStopBits.One : SerialStopBits.Two,
    };
}
