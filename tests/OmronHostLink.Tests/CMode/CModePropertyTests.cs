using System.Buffers;
using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.CMode;

/// <summary>Properties over random commands and over the golden frames.</summary>
public sealed class CModePropertyTests
{
    private static CModeCommand RandomCommand(Random r)
    {
        var areas = new[] { CModeArea.Cio, CModeArea.Lr, CModeArea.Holding, CModeArea.TimerCounterPv, CModeArea.Dm, CModeArea.Auxiliary, CModeArea.Em };
        switch (r.Next(10))
        {
            case 0:
            case 1:
            {
                CModeArea area = r.Next(8) == 0 ? CModeArea.TimerCounterStatus : areas[r.Next(areas.Length)];
                int size = CModeAreaInfo.Size(area);
                int begin = r.Next(size);
                return new AreaReadCommand(area, begin, r.Next(1, Math.Min(9999, size - begin) + 1), area == CModeArea.Em ? r.Next(13) : 0);
            }

            case 2:
            case 3:
            {
                CModeArea area = areas[r.Next(areas.Length)];
                int begin = r.Next(CModeAreaInfo.Size(area));
                int n = r.Next(1, Math.Min(200, CModeAreaInfo.Size(area) - begin) + 1);
                ushort[] words = Enumerable.Range(0, n).Select(_ => (ushort)r.Next(65536)).ToArray();
                return new AreaWriteCommand(area, begin, words, area == CModeArea.Em ? r.Next(13) : 0);
            }

            case 4: return new StatusChangeCommand((PlcMode)r.Next(3));
            case 5: return new ErrorReadCommand(r.Next(2) == 1);
            case 6: return new TestCommand(new string(Enumerable.Range(0, r.Next(0, 123)).Select(_ => (char)r.Next(0x20, 0x7F)).Where(c => c is not ('*' or '@')).ToArray()));
            case 7: return new ForceBitCommand(r.Next(2) == 1, ForceArea.Cio, r.Next(6144), r.Next(16));
            case 8: return new MultipleForceCommand(ForceArea.Holding, r.Next(512), Enumerable.Range(0, 16).Select(_ => new[] { ForceAction.None, ForceAction.Reset, ForceAction.Set, ForceAction.ForcedReset, ForceAction.ForcedSet, ForceAction.Cancel }[r.Next(6)]).ToArray());
            default: return new CModeCommand[] { CModeCommands.StatusReadCommand, CModeCommands.ModelReadCommand, CModeCommands.ForcedCancelCommand, CModeCommands.AbortCommand }[r.Next(4)];
        }
    }

    [Fact]
    public void Every_command_survives_encode_frame_parse_reassemble_parse()
    {
        var r = new Random(20261121);
        for (int i = 0; i < 3000; i++)
        {
            CModeCommand command = RandomCommand(r);
            int unit = r.Next(32);
            var writer = new ArrayBufferWriter<byte>();
            FrameWriter.WriteFrames(writer, command.ToMessage(unit), CModeCommand.PrefixLength + command.FixedTextLength, command.AtomLength);

            // Read the frames back as a PLC would, from an arbitrarily cut stream.
            ReadOnlySequence<byte> buffer = Segments.Cut(writer.WrittenSpan.ToArray(), r);
            var text = new List<byte>();
            string? header = null;
            int parsedUnit = -1;
            bool first = true;
            while (FrameReader.TryReadFrame(ref buffer, first, out ReadOnlySequence<byte> frame, out _) == FrameScanResult.Frame)
            {
                byte[] f = frame.ToArray();
                f.Length.Should().BeLessThanOrEqualTo(first ? FrameWriter.MaxFirstFrameLength : FrameWriter.MaxContinuationFrameLength);
                FrameInfo info = first ? FrameParser.ParseFirst(f) : FrameParser.ParseContinuation(f);
                if (first)
                {
                    header = Encoding.ASCII.GetString(info.Header(f));
                    parsedUnit = info.Unit;
                }

                text.AddRange(info.Text(f).ToArray());
                first = false;
            }

            buffer.Length.Should().Be(0);
            parsedUnit.Should().Be(unit);
            CModeCommand back = CModeCommand.Parse(Encoding.ASCII.GetBytes(header!), text.ToArray());
            back.ToString().Should().Be(command.ToString());
            back.GetType().Should().Be(command.GetType());
        }
    }

    [Fact]
    public void Write_frames_never_split_a_word_and_keep_the_address_and_first_word_in_frame_one()
    {
        for (int n = 1; n <= 400; n++)
        {
            var command = new AreaWriteCommand(CModeArea.Dm, 0, new ushort[n]);
            var writer = new ArrayBufferWriter<byte>();
            int frames = FrameWriter.WriteFrames(writer, command.ToMessage(0), CModeCommand.PrefixLength + command.FixedTextLength, command.AtomLength);
            string[] parts = Encoding.ASCII.GetString(writer.WrittenSpan).Split('\r', StringSplitOptions.RemoveEmptyEntries);
            parts.Should().HaveCount(frames);
            int firstWords = (parts[0].TrimEnd('*').Length - 9 - 2) / 4;
            firstWords.Should().BeGreaterThan(0).And.BeLessThanOrEqualTo(29);
            ((parts[0].TrimEnd('*').Length - 9 - 2) % 4).Should().Be(0);
            foreach (string p in parts.Skip(1))
            {
                ((p.TrimEnd('*').Length - 2) % 4).Should().Be(0, "continuation frames carry whole words");
                (p.Length + 1).Should().BeLessThanOrEqualTo(FrameWriter.MaxContinuationFrameLength);
            }

            (parts[0].Length + 1).Should().BeLessThanOrEqualTo(FrameWriter.MaxFirstFrameLength);
        }
    }

    public static IEnumerable<object[]> GoodSingleFrames => GoldenVectors.Names(v => v.FcsOk && v.Frames.Length == 1 && v.Frames[0] != "@**\r");

    [Theory]
    [MemberData(nameof(GoodSingleFrames))]
    public void Any_single_changed_character_is_detected(string name)
    {
        byte[] frame = GoldenVectors.Get(name).FrameBytes(0);

        // Every position but the closing CR (a frame without its CR never ends: the reader waits and times out).
        for (int i = 0; i < frame.Length - 1; i++)
        {
            for (int c = 0x20; c < 0x80; c++)
            {
                if (c == frame[i])
                {
                    continue;
                }

                byte[] damaged = (byte[])frame.Clone();
                damaged[i] = (byte)c;
                bool accepted = Accepts(damaged);
                accepted.Should().BeFalse($"'{FrameText.Printable(damaged)}' (position {i}) must not pass as a valid final frame");
            }
        }
    }

    [Theory]
    [MemberData(nameof(GoodSingleFrames))]
    public void Any_fragmentation_of_a_frame_with_noise_in_front_reads_the_same_frame(string name)
    {
        byte[] frame = GoldenVectors.Get(name).FrameBytes(0);
        var r = new Random(name.Length);
        for (int i = 0; i < 50; i++)
        {
            byte[] noisy = Encoding.ASCII.GetBytes("\0\x7F~\r#").Take(r.Next(6)).Concat(frame).ToArray();
            ReadOnlySequence<byte> buffer = Segments.Cut(noisy, r);
            FrameReader.TryReadFrame(ref buffer, true, out ReadOnlySequence<byte> read, out _).Should().Be(FrameScanResult.Frame);
            read.ToArray().Should().Equal(frame);
        }
    }

    [Fact]
    public void A_frame_cut_short_before_the_next_one_is_dropped_and_the_next_frame_read()
    {
        byte[] whole = GoldenVectors.Get("c_rd_resp_3w").FrameBytes(0);
        byte[] stream = Encoding.ASCII.GetBytes("@00RD00000AFF").Concat(whole).ToArray(); // a truncated answer, then a whole one
        var buffer = new ReadOnlySequence<byte>(stream);

        FrameReader.TryReadFrame(ref buffer, true, out ReadOnlySequence<byte> frame, out long discarded).Should().Be(FrameScanResult.Frame);

        frame.ToArray().Should().Equal(whole);
        discarded.Should().Be(13);
    }

    [Fact]
    public void Bytes_without_a_CR_are_cut_at_the_documented_bound()
    {
        byte[] endless = Enumerable.Repeat((byte)'0', FrameReader.MaxFrameLength + 10).Prepend((byte)'@').ToArray();
        var buffer = new ReadOnlySequence<byte>(endless);
        FrameReader.TryReadFrame(ref buffer, true, out _, out _).Should().Be(FrameScanResult.Overflow);

        var shorter = new ReadOnlySequence<byte>(endless.AsMemory(0, FrameReader.MaxFrameLength));
        FrameReader.TryReadFrame(ref shorter, true, out _, out _).Should().Be(FrameScanResult.NeedMoreData);
    }

    private static bool Accepts(byte[] frame)
    {
        try
        {
            FrameInfo info = FrameParser.ParseFirst(frame);
            return info.IsFinal;
        }
        catch (HostLinkFrameException)
        {
            return false;
        }
    }
}
