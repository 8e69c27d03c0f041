using System.Buffers;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Tests.CMode;

public class AreaReadCommandSpanTests
{
    [Fact]
    public void WriteFrame_gives_the_published_RD_frame()
    {
        Span<byte> frame = stackalloc byte[32];
        int n = AreaReadCommand.WriteFrame(0, CModeArea.Dm, 0, 10, 0, frame);
        System.Text.Encoding.ASCII.GetString(frame.Slice(0, n)).Should().Be("@00RD0000001057*\r");
        n.Should().Be(AreaReadCommand.GetFrameLength(CModeArea.Dm)).And.Be(17);
    }

    [Theory]
    [InlineData(CModeArea.Dm, 100, 30, 0, 0)]
    [InlineData(CModeArea.Cio, 6000, 144, 0, 7)]
    [InlineData(CModeArea.Holding, 0, 512, 0, 31)]
    [InlineData(CModeArea.Em, 9990, 10, 0xC, 2)]
    [InlineData(CModeArea.TimerCounterStatus, 2048, 5, 0, 3)]
    public void Static_encoders_match_the_command_object(object areaValue, int begin, int count, int bank, int unit)
    {
        // The area arrives as object: the test method is public, the protocol types are internal.
        var area = (CModeArea)areaValue;
        var command = new AreaReadCommand(area, begin, count, bank);
        byte[] expectedMessage = command.ToMessage(unit);
        var expectedFrame = new ArrayBufferWriter<byte>();
        FrameWriter.WriteSingleFrame(expectedFrame, expectedMessage);

        var message = new byte[AreaReadCommand.GetMessageLength(area)];
        AreaReadCommand.WriteMessage(unit, area, begin, count, bank, message).Should().Be(message.Length);
        message.Should().Equal(expectedMessage);

        var frame = new byte[AreaReadCommand.GetFrameLength(area) + 5];
        int n = AreaReadCommand.WriteFrame(unit, area, begin, count, bank, frame);
        frame.AsSpan(0, n).ToArray().Should().Equal(expectedFrame.WrittenSpan.ToArray());
    }

    [Fact]
    public void Static_encoders_validate_before_writing()
    {
        var frame = new byte[40];
        FluentActions.Invoking(() => AreaReadCommand.WriteFrame(32, CModeArea.Dm, 0, 1, 0, frame)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => AreaReadCommand.WriteFrame(0, CModeArea.Dm, 9999, 2, 0, frame)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => AreaReadCommand.WriteFrame(0, CModeArea.Dm, 0, 0, 0, frame)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => AreaReadCommand.WriteFrame(0, CModeArea.Dm, 0, 1, 1, frame)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => AreaReadCommand.WriteFrame(0, CModeArea.Dm, 0, 1, 0, new byte[16])).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => AreaReadCommand.WriteMessage(0, CModeArea.Em, 0, 1, 0, new byte[14])).Should().Throw<ArgumentException>();
    }

    [Fact]
    public void A_30_word_RD_round_trip_allocates_only_the_result()
    {
        // Warm up, then measure: encode the command frame, decode a 30-word answer frame.
        byte[] answer = BuildAnswer(30);
        RoundTrip(answer);
        long before = GC.GetAllocatedBytesForCurrentThread();
        ushort[] words = RoundTrip(answer);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        words.Should().HaveCount(30);
        words[29].Should().Be(29 * 3);
        allocated.Should().BeLessThanOrEqualTo(24 + (30 * 2) + 8, "only the ushort[30] result may be allocated");
    }

    private static ushort[] RoundTrip(byte[] answer)
    {
        Span<byte> tx = stackalloc byte[32];
        int sent = AreaReadCommand.WriteFrame(0, CModeArea.Dm, 100, 30, 0, tx);
        if (tx[sent - 1] != (byte)'\r')
        {
            throw new InvalidOperationException("The frame does not end with CR.");
        }

        FrameInfo info = FrameParser.ParseFirst(answer);
        ReadOnlySpan<byte> data = CModeResponse.GetData(info.Text(answer), "RD", info.Unit);
        var words = new ushort[30];
        CModeResponse.ReadWords(data, words);
        return words;
    }

    private static byte[] BuildAnswer(int count)
    {
        var data = new byte[count * 4];
        for (int i = 0; i < count; i++)
        {
            HexAscii.WriteWord((ushort)(i * 3), data.AsSpan(i * 4));
        }

        var message = new byte[7 + data.Length];
        int n = CModeResponse.WriteMessage(message, 0, "RD", EndCode.NormalCompletion, data);
        var frame = new ArrayBufferWriter<byte>();
        FrameWriter.WriteSingleFrame(frame, message.AsSpan(0, n));
        return frame.WrittenSpan.ToArray();
    }
}
