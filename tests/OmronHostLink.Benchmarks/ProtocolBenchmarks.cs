using System.Text;
using BenchmarkDotNet.Attributes;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Benchmarks;

/// <summary>The pure protocol layer: FCS, RD encode, 30-word decode, 1000-word reassembly, address parsing.</summary>
[MemoryDiagnoser]
public class ProtocolBenchmarks
{
    private readonly byte[] _tx = new byte[32];
    private readonly byte[] _text = new byte[4100];
    private byte[] _fcsInput = [];
    private byte[] _answer30 = [];
    private byte[][] _answer1000 = [];

    [GlobalSetup]
    public void Setup()
    {
        _fcsInput = Encoding.ASCII.GetBytes("@00RD00" + new string('A', 120));
        _answer30 = Frames.Answer("RD", 30)[0];
        _answer1000 = Frames.Answer("RD", 1000);
    }

    /// <summary>FCS over a full 127-character frame body.</summary>
    [Benchmark]
    public byte Fcs127() => Fcs.Compute(_fcsInput);

    /// <summary>RD command frame with FCS, no objects.</summary>
    [Benchmark]
    public int EncodeRd() => AreaReadCommand.WriteFrame(0, CModeArea.Dm, 100, 30, 0, _tx);

    /// <summary>30-word answer: frame parse, FCS check, end code, words.</summary>
    [Benchmark]
    public ushort[] DecodeRd30() => Decode30(_answer30);

    /// <summary>Encode the RD plus decode its 30-word answer: the round trip's protocol work.</summary>
    [Benchmark]
    public ushort[] RoundTripRd30()
    {
        AreaReadCommand.WriteFrame(0, CModeArea.Dm, 100, 30, 0, _tx);
        return Decode30(_answer30);
    }

    /// <summary>1000-word answer in 33 frames: parse and check each, join the text, decode the words.</summary>
    [Benchmark]
    public ushort[] Reassemble1000()
    {
        int length = 0;
        FrameInfo info = FrameParser.ParseFirst(_answer1000[0]);
        info.Text(_answer1000[0]).CopyTo(_text);
        length += info.TextLength;
        for (int i = 1; i < _answer1000.Length; i++)
        {
            info = FrameParser.ParseContinuation(_answer1000[i]);
            info.Text(_answer1000[i]).CopyTo(_text.AsSpan(length));
            length += info.TextLength;
        }

        ReadOnlySpan<byte> data = CModeResponse.GetData(_text.AsSpan(0, length), "RD", 0);
        var words = new ushort[1000];
        CModeResponse.ReadWords(data, words);
        return words;
    }

    /// <summary>A word address.</summary>
    [Benchmark]
    public PlcAddress ParseAddress() => PlcAddress.Parse("D1234");

    /// <summary>An EM bit address (the longest grammar path).</summary>
    [Benchmark]
    public PlcAddress ParseEmBitAddress() => PlcAddress.Parse("E1_100.05");

    private static ushort[] Decode30(byte[] frame)
    {
        FrameInfo info = FrameParser.ParseFirst(frame);
        if (!info.IsFinal || frame[3] != (byte)'R' || frame[4] != (byte)'D')
        {
            throw new InvalidOperationException("Not a single RD answer.");
        }

        ReadOnlySpan<byte> data = CModeResponse.GetData(info.Text(frame), "RD", info.Unit);
        var words = new ushort[30];
        CModeResponse.ReadWords(data, words);
        return words;
    }
}

/// <summary>Answer frames as a PLC sends them.</summary>
internal static class Frames
{
    public static byte[][] Answer(string header, int words)
    {
        var data = new byte[words * 4];
        for (int i = 0; i < words; i++)
        {
            HexAscii.WriteWord((ushort)(i * 13), data.AsSpan(i * 4));
        }

        var message = new byte[7 + data.Length];
        int n = CModeResponse.WriteMessage(message, 0, header, EndCode.NormalCompletion, data);
        var frames = new List<byte[]>();
        ReadOnlySpan<byte> rest = message.AsSpan(0, n);
        bool first = true;
        bool final;
        do
        {
            int length = FrameWriter.NextSegmentLength(rest.Length, first, 7, 4, out final);
            var frame = new byte[length + FrameWriter.FinalOverhead];
            int written = FrameWriter.WriteFrame(rest.Slice(0, length), final, frame);
            frames.Add(frame.AsSpan(0, written).ToArray());
            rest = rest.Slice(length);
            first = false;
        }
        while (!final);

        return frames.ToArray();
    }
}
