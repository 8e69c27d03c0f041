using System.Diagnostics;

namespace OmronHostLink.Benchmarks;

/// <summary>A pair of pseudo-terminals joined by socat: what is written to <see cref="PathA"/> comes out of <see cref="PathB"/> and back.</summary>
internal sealed class PtyPair : IAsyncDisposable
{
    private readonly Process _socat;

    private PtyPair(Process socat, string pathA, string pathB)
    {
        _socat = socat;
        PathA = pathA;
        PathB = pathB;
    }

    public string PathA { get; }

    public string PathB { get; }

    public static async Task<PtyPair> StartAsync()
    {
        string stem = Path.Combine(Path.GetTempPath(), $"ohl-bench-{Environment.ProcessId}-{Guid.NewGuid():N}");
        string a = stem + "-A";
        string b = stem + "-B";
        var start = new ProcessStartInfo("socat") { UseShellExecute = false, RedirectStandardError = true };
        foreach (string argument in new[] { "-d", "-d", $"pty,raw,echo=0,link={a}", $"pty,raw,echo=0,link={b}" })
        {
            start.ArgumentList.Add(argument);
        }

        Process socat = Process.Start(start) ?? throw new InvalidOperationException("socat did not start (apt-get install socat).");
        socat.ErrorDataReceived += (_, _) => { };
        socat.BeginErrorReadLine();
        var clock = Stopwatch.StartNew();
        while (!(File.Exists(a) && File.Exists(b)))
        {
            if (socat.HasExited || clock.Elapsed > TimeSpan.FromSeconds(5))
            {
                throw new InvalidOperationException("socat did not make the pty pair within 5 s.");
            }

            await Task.Delay(20);
        }

        return new PtyPair(socat, a, b);
    }

    public async ValueTask DisposeAsync()
    {
        if (!_socat.HasExited)
        {
            _socat.Kill();
            await _socat.WaitForExitAsync();
        }

        _socat.Dispose();
        File.Delete(PathA);
        File.Delete(PathB);
    }
}
