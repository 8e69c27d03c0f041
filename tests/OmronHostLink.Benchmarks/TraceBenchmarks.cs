using BenchmarkDotNet.Attributes;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// The client's trace option on the read path of <see cref="ReadPathBenchmarks"/> (one word, the answer on the caller's
/// thread): off (the default: the link's frame tap is null, one check a frame) and on (every frame written to a pcap).
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class TraceBenchmarks
{
    private HostLinkClient _client = null!;
    private string _trace = "";

    [Params(false, true)]
    public bool Trace { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        _trace = Path.Combine(Path.GetTempPath(), $"ohl-trace-bench-{Environment.ProcessId}.pcap");
        var stream = new ReadPathBenchmarks.AnsweringStream(1, onThreadPool: false);
        _client = HostLinkClient.ForStream(stream, new HostLinkClientOptions { ReadRetries = 0, TraceFile = Trace ? _trace : null });
        _ = ReadWord();
    }

    [GlobalCleanup]
    public void Cleanup()
    {
        _client.DisposeAsync().AsTask().GetAwaiter().GetResult();
        File.Delete(_trace);
    }

    [Benchmark]
    public ushort ReadWord() => _client.ReadWordsAsync("D100", 1).GetAwaiter().GetResult()[0];
}
