using System.ComponentModel;
using System.Diagnostics;
using System.Text;
using OmronHostLink.Transports;

namespace OmronHostLink.Testing;

/// <summary>
/// A connected pair of pseudo-terminals made by <c>socat</c>: bytes written to <see cref="PathA"/> come out of
/// <see cref="PathB"/> and the other way round, like a null-modem cable between two serial ports.
/// </summary>
/// <remarks>
/// The paths are unique symbolic links in the temp directory. socat must be installed (Debian/Ubuntu:
/// <c>apt-get install socat</c>); the tests that use this fail rather than skip without it, so CI cannot silently
/// lose them. Ptys ignore baud rate and parity. Tests open the ends through the package's serial transport
/// (<see cref="OpenAsync(string, SerialLineSettings?)"/>), as a user's program would.
/// </remarks>
public sealed class SocatPtyPair : IAsyncDisposable
{
    private static readonly TimeSpan StartTimeout = TimeSpan.FromSeconds(5);

    private readonly Process _process;
    private readonly StringBuilder _log;
    private int _closed;

    private SocatPtyPair(Process process, StringBuilder log, string pathA, string pathB)
    {
        _process = process;
        _log = log;
        PathA = pathA;
        PathB = pathB;
    }

    /// <summary>socat's process id.</summary>
    public int ProcessId => _process.Id;

    /// <summary>One end: a symbolic link to a /dev/pts/N.</summary>
    public string PathA { get; }

    /// <summary>The other end.</summary>
    public string PathB { get; }

    /// <summary>
    /// Opens <paramref name="path"/> through the package's <see cref="SerialTransport"/> (System.IO.Ports) with
    /// <paramref name="settings"/> (default: Host Link's 9600 7E2); disposing the stream closes the port.
    /// </summary>
    public static async Task<Stream> OpenAsync(string path, SerialLineSettings? settings = null)
    {
        settings ??= new SerialLineSettings();
        settings.PortName = path;
        var transport = new SerialTransport(settings);
        return await transport.OpenAsync(CancellationToken.None).ConfigureAwait(false);
    }

    /// <summary>What socat has logged so far (for failure messages).</summary>
    public string Log
    {
        get
        {
            lock (_log)
            {
                return _log.ToString();
            }
        }
    }

    /// <summary>Starts socat and waits (at most 5 s) until both links exist.</summary>
    /// <exception cref="InvalidOperationException">socat is not installed, exited early, or did not get ready in time.</exception>
    public static Task<SocatPtyPair> StartAsync()
    {
        string stem = Path.Combine(Path.GetTempPath(), $"ohl-pty-{Environment.ProcessId}-{Guid.NewGuid():N}");
        return StartAsync(stem + "-A", stem + "-B");
    }

    /// <summary>
    /// Starts socat again on the same link names after <see cref="CloseAsync"/>, as a USB adapter that comes back does
    /// (new ptys behind the same paths).
    /// </summary>
    public Task<SocatPtyPair> RestartAsync() => StartAsync(PathA, PathB);

    /// <summary>Starts socat with the given link paths (they must not exist).</summary>
    public static async Task<SocatPtyPair> StartAsync(string pathA, string pathB)
    {

        // socat writes nothing to stdout; its log (-d -d) goes to stderr.
        var startInfo = new ProcessStartInfo("socat")
        {
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string argument in new[] { "-d", "-d", $"pty,raw,echo=0,link={pathA}", $"pty,raw,echo=0,link={pathB}" })
        {
            startInfo.ArgumentList.Add(argument);
        }

        var log = new StringBuilder();
        var ready = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        var process = new Process { StartInfo = startInfo, EnableRaisingEvents = true };
        void OnLogLine(string? line)
        {
            if (line is null)
            {
                ready.TrySetException(new InvalidOperationException("socat closed its log before it was ready."));
                return;
            }

            lock (log)
            {
                log.AppendLine(line);
            }

            // Logged (with -d -d) once both ptys exist and their links are made.
            if (line.Contains("starting data transfer loop", StringComparison.Ordinal))
            {
                ready.TrySetResult();
            }
        }

        process.Exited += (_, _) => ready.TrySetException(new InvalidOperationException($"socat exited with code {SafeExitCode(process)} before it was ready."));

        try
        {
            process.Start();
        }
        catch (Win32Exception ex)
        {
            process.Dispose();
            throw new InvalidOperationException(
                "socat is not installed or not on PATH; the serial-port tests need it to make pseudo-terminal pairs. Install it (Debian/Ubuntu: apt-get install socat).",
                ex);
        }

        // The log is read on a thread of its own for as long as socat runs: Process.BeginErrorReadLine reads a pipe
        // with a blocking read on a thread-pool thread, which on a 2-core machine is half the pool's minimum.
        var reader = new Thread(() =>
        {
            try
            {
                string? line;
                while ((line = process.StandardError.ReadLine()) is not null)
                {
                    OnLogLine(line);
                }
            }
            catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException)
            {
            }

            OnLogLine(null);
        })
        {
            IsBackground = true,
            Name = "socat log",
        };
        reader.Start();
        var pair = new SocatPtyPair(process, log, pathA, pathB);
        try
        {
            await ready.Task.WaitAsync(StartTimeout).ConfigureAwait(false);
            if (!File.Exists(pathA) || !File.Exists(pathB))
            {
                throw new InvalidOperationException($"socat reported ready but {pathA} or {pathB} does not exist.");
            }

            return pair;
        }
        catch (Exception ex)
        {
            string socatLog = pair.Log;
            await pair.DisposeAsync().ConfigureAwait(false);
            throw new InvalidOperationException($"Could not start a socat pty pair: {ex.Message}\nsocat log:\n{socatLog}", ex);
        }
    }

    /// <summary>Kills socat, so that both ptys hang up and vanish (for "link lost" tests). Idempotent.</summary>
    public async Task CloseAsync()
    {
        if (Interlocked.Exchange(ref _closed, 1) != 0)
        {
            return;
        }

        try
        {
            if (!_process.HasExited)
            {
                _process.Kill();
            }
        }
        catch (InvalidOperationException)
        {
            // Exited meanwhile.
        }

        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(5));
        try
        {
            await _process.WaitForExitAsync(timeout.Token).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            // Left to the OS; nothing more we can do.
        }

        // SIGKILL gives socat no chance to remove its links.
        TryDelete(PathA);
        TryDelete(PathB);
    }

    /// <summary>Kills socat (if still running) and releases the process.</summary>
    public async ValueTask DisposeAsync()
    {
        await CloseAsync().ConfigureAwait(false);
        _process.Dispose();
    }

    private static void TryDelete(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (IOException)
        {
        }
        catch (UnauthorizedAccessException)
        {
        }
    }

    private static string SafeExitCode(Process process)
    {
        try
        {
            return process.ExitCode.ToString(System.Globalization.CultureInfo.InvariantCulture);
        }
        catch (InvalidOperationException)
        {
            return "?";
        }
    }
}
