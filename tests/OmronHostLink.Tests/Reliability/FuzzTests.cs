using System.Buffers;
using System.Diagnostics;
using System.Globalization;
using System.Text;
using OmronHostLink.Link;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Protocol;
using Xunit.Abstractions;

namespace OmronHostLink.Tests.Reliability;

/// <summary>
/// Random and mutated frames through every decoder, host side and PLC side. Only the documented exception types may
/// escape:
/// <list type="bullet">
/// <item>host side (FrameReader, FrameParser, CModeResponse.*, FinsResponse.Parse/ParseFrame, the FINS data decoders):
/// <see cref="HostLinkFrameException"/>, <see cref="HostLinkEndCodeException"/> (an end code other than 00, IC), and
/// <see cref="FinsEndCodeException"/> (FinsResponse.ThrowIfError);</item>
/// <item>PLC side (CModeCommand.Parse, FinsMessage.ParseCommand/ParseCommandFrame, FinsCommandMessage.ToCommand):
/// <see cref="CModeCommandRejectedException"/>, <see cref="HostLinkFrameException"/>, <see cref="FinsFormatException"/>;
/// the simulator's frame exchange throws nothing at all: every input gets an end code or silence.</item>
/// </list>
/// Inputs: the golden vectors' frames mutated 1-4 times (bit flips, replaced, inserted and deleted characters,
/// truncation, duplicated slices, CR / <c>*</c> / <c>@</c> injection, two frames spliced), half of them with the FCS
/// recomputed so that the decoders behind the FCS check see the damage, plus wholly random frames. The count is
/// <c>HOSTLINK_FUZZ_FRAMES</c> (CI default 50,000; the full run is 1,000,000) from seed <c>HOSTLINK_FUZZ_SEED</c>.
/// </summary>
public sealed class FuzzTests(ITestOutputHelper output)
{
    private static readonly byte[] Special = "\r*@"u8.ToArray();
    private static readonly string[] CModeHeaders = { "RR", "RL", "RH", "RC", "RG", "RD", "RJ", "RE", "WR", "WL", "WH", "WC", "WD", "WJ", "WE", "MS", "SC", "MF", "MM", "TS", "KS", "KR", "FK", "KC", "XZ", "R#", "FA", "IC", "ZZ" };

    private static int Frames => EnvInt("HOSTLINK_FUZZ_FRAMES", 50_000);

    private static int Seed => EnvInt("HOSTLINK_FUZZ_SEED", 1);

    [Fact]
    public void Host_and_plc_side_decoders_raise_only_documented_exceptions()
    {
        var generator = new Generator(Seed);
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = new[] { 0, 1, 31 } });
        var exchange = new HostLinkExchange(new HostLinkResponder(plc), plc.Options.Units);
        var tally = new Tally();
        var clock = Stopwatch.StartNew();
        long slowest = 0;
        for (int i = 0; i < Frames; i++)
        {
            byte[] input = generator.Next();
            long started = Stopwatch.GetTimestamp();
            tally.Input = input;
            FeedReader(input, generator.Random, tally);
            Decode(input, tally);
            Plc(input, exchange, tally);
            slowest = Math.Max(slowest, Stopwatch.GetTimestamp() - started);
            if (tally.Unexpected.Count > 0)
            {
                break;
            }
        }

        double slowestMs = slowest * 1000.0 / Stopwatch.Frequency;
        string report = $"Fuzz: {Frames} inputs (seed {Seed}) in {clock.Elapsed.TotalSeconds:0.0} s, slowest input {slowestMs:0.0} ms; frames cut {tally.FramesCut}, parsed {tally.Parsed}, decoded {tally.Decoded}; "
            + $"exceptions: {string.Join(", ", tally.Expected.OrderByDescending(kv => kv.Value).Select(kv => $"{kv.Key} {kv.Value}"))}; unexpected {tally.Unexpected.Count}";
        output.WriteLine(report);
        Console.WriteLine(report);
        tally.Unexpected.Should().BeEmpty();
        slowestMs.Should().BeLessThan(2000, "no input may make a decoder loop");
        tally.Parsed.Should().BeGreaterThan(Frames / 10, "enough inputs must get past the frame checks to reach the decoders");
    }

    [Fact]
    public void A_stream_without_CR_is_cut_at_MaxFrameLength_in_any_fragmentation()
    {
        var random = new Random(Seed);
        for (int round = 0; round < 200; round++)
        {
            bool expectStart = random.Next(2) == 0;
            var buffered = new List<byte>();
            int fed = 0;
            FrameScanResult result = FrameScanResult.NeedMoreData;
            while (result == FrameScanResult.NeedMoreData)
            {
                // '@' first (so noise skipping does not eat it all), then anything but CR.
                int n = 1 + random.Next(200);
                for (int k = 0; k < n; k++)
                {
                    buffered.Add(fed + k == 0 ? (byte)'@' : (byte)random.Next(0x20, 0x7F));
                }

                fed += n;
                var sequence = Segments(buffered.ToArray(), random);
                result = FrameReader.TryReadFrame(ref sequence, expectStart, out _, out _);
                buffered = sequence.ToArray().ToList();
                buffered.Count.Should().BeLessThanOrEqualTo(FrameReader.MaxFrameLength + 200, "nothing is buffered past the bound and one read");
            }

            result.Should().Be(FrameScanResult.Overflow);
            fed.Should().BeGreaterThan(FrameReader.MaxFrameLength).And.BeLessThanOrEqualTo(FrameReader.MaxFrameLength + 200);
        }

        // A CR after the bound: the over-long frame is refused, not returned.
        // ('@' starts it and no other '@' follows: an earlier '@' would only mark a frame cut short.)
        byte[] longFrame = new[] { (byte)'@' }.Concat(Enumerable.Repeat((byte)'0', FrameReader.MaxFrameLength + 5)).Concat(new[] { (byte)'\r' }).ToArray();
        var whole = new ReadOnlySequence<byte>(longFrame);
        FrameReader.TryReadFrame(ref whole, expectStart: true, out _, out _).Should().Be(FrameScanResult.Overflow);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public async Task A_link_flooded_without_CR_fails_typed_and_buffers_a_bounded_amount(bool withAt)
    {
        // An endless stream of noise: with '@' (a frame that never ends) or without (noise before a frame that never comes).
        var flood = new FloodStream(withAt ? (byte)'@' : (byte)'x');
        await using var client = HostLinkClient.ForStream(flood, new HostLinkClientOptions
        {
            LineTiming = new OmronHostLink.Transports.LineTiming(1_000_000, 10),
            TurnaroundAllowance = TimeSpan.FromMilliseconds(100),
            ReadRetries = 0,
        });

        Exception e = (await FluentActions.Awaiting(() => client.ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkException>()).Which;
        if (withAt)
        {
            e.Should().BeOfType<HostLinkFrameException>().Which.Error.Should().Be(FrameError.TooLong);
        }
        else
        {
            e.Should().BeOfType<HostLinkTimeoutException>();
        }

        // Between transactions nobody reads the buffer: the pump must stop at its pause threshold, not buffer the flood.
        // The flood answers each read after a thread-pool hop, so rounds of the thread pool are what a pump needs to go
        // on: once the count has held still for a round of hops, it must hold still for 500 more.
        long first;
        int tries = 0;
        do
        {
            (++tries).Should().BeLessThan(500, "a bounded pump stops");
            first = flood.Served;
            await ThreadPoolRounds(20);
        }
        while (flood.Served != first);

        await ThreadPoolRounds(500);
        flood.Served.Should().Be(first, "the pump is held back by the bounded buffer (64 KiB) while nobody reads");
        flood.Served.Should().BeGreaterThanOrEqualTo(FrameChannel.PauseThreshold, "the pump ran until the buffer reached its bound");
        output.WriteLine($"flood with '@' {withAt}: {e.GetType().Name}; the pump stopped after {first} bytes served");
    }

    private static int EnvInt(string name, int fallback)
        => int.TryParse(Environment.GetEnvironmentVariable(name), NumberStyles.Integer, CultureInfo.InvariantCulture, out int v) && v > 0 ? v : fallback;

    /// <summary>Feeds the input to the frame reader in random fragments, with both start modes, and decodes every frame cut.</summary>
    private static void FeedReader(byte[] input, Random random, Tally tally)
    {
        bool expectStart = random.Next(4) != 0;
        ReadOnlySequence<byte> sequence = Segments(input, random);
        for (int guard = 0; ; guard++)
        {
            if (guard > input.Length + 2)
            {
                tally.Fail(new InvalidOperationException("FrameReader made no progress."));
                return;
            }

            long before = sequence.Length;
            FrameScanResult scan;
            ReadOnlySequence<byte> frame;
            try
            {
                scan = FrameReader.TryReadFrame(ref sequence, expectStart, out frame, out _);
            }
            catch (Exception e)
            {
                tally.Fail(e);
                return;
            }

            if (scan != FrameScanResult.Frame)
            {
                if (sequence.Length > FrameReader.MaxFrameLength + 1 && scan == FrameScanResult.NeedMoreData)
                {
                    tally.Fail(new InvalidOperationException($"FrameReader holds {sequence.Length} bytes without reporting Overflow."));
                }

                return;
            }

            if (frame.Length > FrameReader.MaxFrameLength + 1 || sequence.Length >= before)
            {
                tally.Fail(new InvalidOperationException("FrameReader returned an over-long frame or consumed nothing."));
                return;
            }

            tally.FramesCut++;
            Decode(frame.ToArray(), tally);
        }
    }

    private static ReadOnlySequence<byte> Segments(byte[] data, Random random)
    {
        if (data.Length < 2 || random.Next(3) == 0)
        {
            return new ReadOnlySequence<byte>(data);
        }

        var first = new Segment(data.AsMemory(0, 0));
        Segment last = first;
        int at = 0;
        while (at < data.Length)
        {
            int n = Math.Min(data.Length - at, 1 + random.Next(40));
            last = last.Append(data.AsMemory(at, n));
            at += n;
        }

        return new ReadOnlySequence<byte>(first, 0, last, last.Memory.Length);
    }

    /// <summary>Every host-side decoder on a frame (and on its text when it parses).</summary>
    private static void Decode(byte[] frame, Tally tally)
    {
        tally.Try(() => FrameParser.ParseContinuation(frame));
        FrameInfo info = default;
        if (!tally.Try(() => info = FrameParser.ParseFirst(frame)))
        {
            return;
        }

        tally.Parsed++;
        byte[] text = info.Text(frame).ToArray();
        int unit = info.Unit;
        string header = Encoding.ASCII.GetString(frame, 3, 2);

        // C-mode response decoders, on the whole text and on what follows an end code.
        tally.Try(() => CModeResponse.ReadEndCode(text));
        tally.Try(() => CModeResponse.GetData(text, header, unit).Length);
        byte[] data = text.Length >= 2 ? text.AsSpan(2).ToArray() : text;
        tally.Try(() => CModeResponse.ReadWords(data, new ushort[data.Length / 4]));
        tally.Try(() => CModeResponse.ReadWords(data, new ushort[3]));
        tally.Try(() => CModeResponse.ReadFlags(data, new bool[data.Length]));
        tally.Try(() => CModeResponse.ReadStatus(data));
        tally.Try(() => CModeResponse.ReadErrors(data));
        tally.Try(() => CModeResponse.ReadModel(data));
        tally.Try(() => CModeResponse.CheckTestEcho(text, "OMRON"u8, unit));

        // FINS.
        tally.Try(() => FinsResponse.ParseFrame(frame, unit, FinsHeader.Direct(0), 0x0101));
        FinsResponse? response = null;
        tally.Try(() => response = FinsResponse.Parse(text, unit));
        byte sid = text.Length >= 10 && HexAscii.TryParseByte(text.AsSpan(8, 2), out byte s) ? s : (byte)0;
        tally.Try(() => FinsResponse.Parse(text, unit, FinsHeader.Direct(sid), 0x0101));
        byte[] fins = response?.Data.ToArray() ?? FinsBytesOf(text);
        if (response is not null)
        {
            tally.Decoded++;
            tally.Try(response.ThrowIfError);
        }

        DecodeFins(fins, tally);
    }

    private static byte[] FinsBytesOf(byte[] text)
    {
        var bytes = new byte[text.Length / 2];
        return FinsBytes.TryParseHex(text.AsSpan(0, bytes.Length * 2), bytes) ? bytes : text;
    }

    private static readonly MultipleMemoryAreaReadCommand Multiple = new(new[]
    {
        new FinsMemoryAddress(0x82, 100),
        new FinsMemoryAddress(0x30, 10, 5),
        new FinsMemoryAddress(0xB0, 1),
    });

    private static void DecodeFins(byte[] data, Tally tally)
    {
        tally.Try(() => FinsWords.Read(data, data.Length / 2));
        tally.Try(() => FinsWords.Read(data, 2));
        tally.Try(() => FinsBits.Read(data, data.Length));
        tally.Try(() => FinsBits.Read(data, 1));
        tally.Try(() => FinsCpuStatus.Read(data));
        tally.Try(() => FinsCpuUnitData.Read(data));
        tally.Try(() => FinsCycleTime.Read(data));
        tally.Try(() => FinsClock.Read(data));
        tally.Try(() => FinsErrorLog.Read(data));
        tally.Try(() => FinsMultipleReadValue.ReadAll(data, Multiple));
    }

    /// <summary>The PLC side: the command parsers (documented exceptions only) and the simulator's exchange (none).</summary>
    private static void Plc(byte[] input, HostLinkExchange exchange, Tally tally)
    {
        try
        {
            exchange.Receive(input);
        }
        catch (Exception e)
        {
            tally.Fail(e);
        }

        if (input.Length < 5)
        {
            return;
        }

        byte[] header = input.AsSpan(3, 2).ToArray();
        ReadOnlySpan<byte> rest = input.AsSpan(5);
        int end = rest.IndexOf((byte)'\r');
        byte[] text = (end >= 0 ? rest.Slice(0, end) : rest).ToArray();
        if (text.Length >= 4 && text[^1] == (byte)'*')
        {
            text = text.AsSpan(0, text.Length - 3).ToArray();
        }

        tally.Try(() => CModeCommand.Parse(header, text));
        FinsCommandMessage? message = null;
        tally.Try(() => message = FinsMessage.ParseCommand(text, 0));
        tally.Try(() => FinsMessage.ParseCommandFrame(input));
        if (message is not null)
        {
            tally.Try(() => message.ToCommand());
        }
    }

    private sealed class Tally
    {
        public Dictionary<string, int> Expected { get; } = new();

        public List<string> Unexpected { get; } = new();

        public byte[] Input { get; set; } = Array.Empty<byte>();

        public long FramesCut { get; set; }

        public long Parsed { get; set; }

        public long Decoded { get; set; }

        public bool Try(Action action)
        {
            try
            {
                action();
                return true;
            }
            catch (Exception e) when (e is HostLinkFrameException or HostLinkEndCodeException or FinsEndCodeException or CModeCommandRejectedException or FinsFormatException)
            {
                string key = e.GetType().Name;
                Expected[key] = Expected.TryGetValue(key, out int n) ? n + 1 : 1;
                return false;
            }
            catch (Exception e)
            {
                Fail(e);
                return false;
            }
        }

        public bool Try<T>(Func<T> func) => Try(() => { _ = func(); });

        public void Fail(Exception e)
        {
            if (Unexpected.Count < 10)
            {
                Unexpected.Add($"{e.GetType().Name} for input '{FrameText.Printable(Input)}': {e}");
            }
        }
    }

    /// <summary>Golden-vector frames, mutated; and random frames.</summary>
    private sealed class Generator
    {
        private readonly byte[][] _seeds;

        public Generator(int seed)
        {
            Random = new Random(seed);
            _seeds = GoldenVectors.All.SelectMany(v => v.Frames).Select(f => Encoding.ASCII.GetBytes(f)).ToArray();
        }

        public Random Random { get; }

        public byte[] Next()
        {
            int kind = Random.Next(10);
            List<byte> frame = kind switch
            {
                0 => RandomFrame(),
                1 => RandomFinsResponse(),
                _ => _seeds[Random.Next(_seeds.Length)].ToList(),
            };
            if (kind > 1 || (kind == 1 && Random.Next(2) == 0))
            {
                int mutations = 1 + Random.Next(4);
                for (int m = 0; m < mutations; m++)
                {
                    Mutate(frame);
                }

                if (Random.Next(2) == 0)
                {
                    FixFcs(frame);
                }
            }

            return frame.ToArray();
        }

        private List<byte> RandomFrame()
        {
            var body = new List<byte> { (byte)'@' };
            body.AddRange(Encoding.ASCII.GetBytes(Random.Next(40).ToString("D2", CultureInfo.InvariantCulture)));
            body.AddRange(Encoding.ASCII.GetBytes(CModeHeaders[Random.Next(CModeHeaders.Length)]));
            int n = Random.Next(Random.Next(4) == 0 ? 1300 : 130);
            bool hex = Random.Next(2) == 0;
            for (int i = 0; i < n; i++)
            {
                body.Add(hex ? HexAscii.Nibble(Random.Next(16)) : (byte)Random.Next(0x20, 0x7F));
            }

            body.AddRange(Encoding.ASCII.GetBytes(Fcs.Compute(body.ToArray()).ToString("X2", CultureInfo.InvariantCulture)));
            body.Add((byte)'*');
            body.Add((byte)'\r');
            return body;
        }

        /// <summary>A well-formed FA response (end code 00, ICF 40, a common command code, random response code and data), to reach the FINS decoders.</summary>
        private List<byte> RandomFinsResponse()
        {
            ushort[] codes = { 0x0101, 0x0104, 0x0501, 0x0601, 0x0620, 0x0701, 0x2102 };
            int[] lengths = { 0, 1, 2, 6, 12, 40, 26, 7, 16, 36 };
            var bytes = new List<byte> { 0x40, 0x00, 0x00, (byte)Random.Next(256) };
            ushort code = codes[Random.Next(codes.Length)];
            bytes.Add((byte)(code >> 8));
            bytes.Add((byte)code);
            ushort end = Random.Next(3) == 0 ? (ushort)Random.Next(0x10000) : (ushort)(Random.Next(2) == 0 ? 0x0000 : 0x0040);
            bytes.Add((byte)(end >> 8));
            bytes.Add((byte)end);
            int n = Random.Next(3) == 0 ? Random.Next(540) : lengths[Random.Next(lengths.Length)] + (Random.Next(4) == 0 ? Random.Next(3) - 1 : 0);
            for (int i = 0; i < n; i++)
            {
                bytes.Add((byte)Random.Next(Random.Next(2) == 0 ? 2 : 256));
            }

            var body = new List<byte>();
            body.AddRange(Encoding.ASCII.GetBytes($"@{Random.Next(32):D2}FA00"));
            foreach (byte b in bytes)
            {
                body.Add(HexAscii.Nibble(b >> 4));
                body.Add(HexAscii.Nibble(b & 0xF));
            }

            body.AddRange(Encoding.ASCII.GetBytes(Fcs.Compute(body.ToArray()).ToString("X2", CultureInfo.InvariantCulture)));
            body.Add((byte)'*');
            body.Add((byte)'\r');
            return body;
        }

        private void Mutate(List<byte> f)
        {
            int at = f.Count == 0 ? 0 : Random.Next(f.Count);
            switch (Random.Next(9))
            {
                case 0 when f.Count > 0:
                    f[at] ^= (byte)(1 << Random.Next(8));
                    break;
                case 1 when f.Count > 0:
                    f[at] = (byte)Random.Next(256);
                    break;
                case 2:
                    f.Insert(at, (byte)Random.Next(256));
                    break;
                case 3 when f.Count > 0:
                    f.RemoveRange(at, Math.Min(f.Count - at, 1 + Random.Next(4)));
                    break;
                case 4:
                    f.RemoveRange(at, f.Count - at);
                    break;
                case 5 when f.Count > 0:
                    int n = Math.Min(f.Count - at, 1 + Random.Next(20));
                    f.InsertRange(at, f.GetRange(at, n));
                    break;
                case 6:
                    f.Insert(at, Special[Random.Next(Special.Length)]);
                    break;
                case 7 when f.Count > 0:
                    f[at] = Special[Random.Next(Special.Length)];
                    break;
                case 8:
                    f.InsertRange(at, _seeds[Random.Next(_seeds.Length)]);
                    break;
            }
        }

        /// <summary>Recomputes the FCS of a frame still ending in FCS*CR or FCS CR, so the damage reaches the decoders.</summary>
        private static void FixFcs(List<byte> f)
        {
            int end = f.Count;
            if (end < 4 || f[end - 1] != (byte)'\r')
            {
                return;
            }

            int fcsEnd = f[end - 2] == (byte)'*' ? end - 2 : end - 1;
            int body = fcsEnd - 2;
            if (body < 1)
            {
                return;
            }

            byte fcs = Fcs.Compute(f.GetRange(0, body).ToArray());
            f[body] = HexAscii.Nibble(fcs >> 4);
            f[body + 1] = HexAscii.Nibble(fcs & 0xF);
        }
    }

    /// <summary>A stream that never ends: every read returns a full buffer of one byte value; writes go to <see cref="Stream.Null"/>.</summary>
    /// <summary>Hops to the thread pool <paramref name="rounds"/> times: each hop queues behind the work already there.</summary>
    private static async Task ThreadPoolRounds(int rounds)
    {
        for (int i = 0; i < rounds; i++)
        {
            await Task.Run(static () => { });
        }
    }

    private sealed class FloodStream(byte value) : PassThroughStream(Null)
    {
        private long _served;

        public long Served => Interlocked.Read(ref _served);

        public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        {
            await Task.Yield();
            buffer.Span.Fill(value);
            Interlocked.Add(ref _served, buffer.Length);
            return buffer.Length;
        }
    }

    private sealed class Segment : ReadOnlySequenceSegment<byte>
    {
        public Segment(ReadOnlyMemory<byte> memory) => Memory = memory;

        public Segment Append(ReadOnlyMemory<byte> memory)
        {
            var next = new Segment(memory) { RunningIndex = RunningIndex + Memory.Length };
            Next = next;
            return next;
        }
    }
}
