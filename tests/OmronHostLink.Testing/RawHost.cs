using System.Diagnostics;
using System.Text;
using System.Threading.Channels;
using FluentAssertions;
using OmronHostLink.Protocol;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Testing;

/// <summary>
/// A raw test host on the far end of an in-memory link to a simulated PLC: writes raw frames, reads raw bytes with
/// their arrival times. No client classes involved.
/// </summary>
public sealed class RawHost : IAsyncDisposable
{
    public static readonly TimeSpan DefaultTimeout = TimeSpan.FromSeconds(5);

    private readonly Stream _hostEnd;
    private readonly Channel<(byte Value, long Timestamp)> _received = Channel.CreateUnbounded<(byte, long)>();
    private readonly Task _pump;
    private readonly CancellationTokenSource _stop = new();

    private RawHost(VirtualPlc plc, Stream hostEnd, Stream plcEnd)
    {
        Plc = plc;
        _hostEnd = hostEnd;
        PlcEnd = plcEnd;
        Session = plc.RunAsync(plcEnd, _stop.Token);
        _pump = Task.Run(PumpAsync);
    }

    public VirtualPlc Plc { get; }

    public Stream PlcEnd { get; }

    /// <summary>The simulator session task.</summary>
    public Task Session { get; }

    public static RawHost Start(VirtualPlc? plc = null)
    {
        var (hostEnd, plcEnd) = InMemoryLink.CreatePair();
        return new RawHost(plc ?? new VirtualPlc(), hostEnd, plcEnd);
    }

    public static RawHost Start(VirtualPlcOptions options) => Start(new VirtualPlc(options));

    /// <summary>Frames a single-frame command: message + FCS + <c>*</c>CR.</summary>
    public static string Command(string message)
    {
        byte[] m = Encoding.ASCII.GetBytes(message);
        return message + Fcs.Compute(m).ToString("X2", System.Globalization.CultureInfo.InvariantCulture) + "*\r";
    }

    /// <summary>Frames a non-final frame: text + FCS + CR.</summary>
    public static string Delimited(string text)
    {
        byte[] m = Encoding.ASCII.GetBytes(text);
        return text + Fcs.Compute(m).ToString("X2", System.Globalization.CultureInfo.InvariantCulture) + "\r";
    }

    public async Task SendAsync(string raw)
    {
        await _hostEnd.WriteAsync(Encoding.ASCII.GetBytes(raw));
        await _hostEnd.FlushAsync();
    }

    public async Task SendAsync(byte[] raw)
    {
        await _hostEnd.WriteAsync(raw);
        await _hostEnd.FlushAsync();
    }

    /// <summary>Sends a frame and reads one frame back.</summary>
    public async Task<string> TransactAsync(string raw)
    {
        await SendAsync(raw);
        return await ReadFrameAsync();
    }

    /// <summary>Reads up to and including the next CR.</summary>
    public async Task<string> ReadFrameAsync(TimeSpan? timeout = null)
        => (await ReadFrameTimedAsync(timeout)).Frame;

    /// <summary>Reads up to and including the next CR, with the arrival time (Stopwatch ticks) of its first and last byte.</summary>
    public async Task<(string Frame, long First, long Last)> ReadFrameTimedAsync(TimeSpan? timeout = null)
    {
        using var cts = new CancellationTokenSource(timeout ?? DefaultTimeout);
        var sb = new StringBuilder();
        long first = 0;
        long last = 0;
        try
        {
            while (true)
            {
                var (value, timestamp) = await _received.Reader.ReadAsync(cts.Token);
                if (sb.Length == 0)
                {
                    first = timestamp;
                }

                last = timestamp;
                sb.Append((char)value);
                if (value == '\r')
                {
                    return (sb.ToString(), first, last);
                }
            }
        }
        catch (OperationCanceledException)
        {
            throw new TimeoutException($"No CR-terminated frame within the timeout; received so far: '{FrameText.Printable(Encoding.ASCII.GetBytes(sb.ToString()))}'.");
        }
    }

    /// <summary>Everything that arrives until the line has been quiet for <paramref name="quiet"/>.</summary>
    public async Task<string> ReadUntilQuietAsync(TimeSpan quiet)
    {
        var sb = new StringBuilder();
        while (true)
        {
            using var cts = new CancellationTokenSource(quiet);
            try
            {
                var (value, _) = await _received.Reader.ReadAsync(cts.Token);
                sb.Append((char)value);
            }
            catch (OperationCanceledException)
            {
                return sb.ToString();
            }
        }
    }

    /// <summary>Asserts that nothing arrives within <paramref name="wait"/> (default 200 ms).</summary>
    public async Task ExpectSilenceAsync(TimeSpan? wait = null)
    {
        string got = await ReadUntilQuietAsync(wait ?? TimeSpan.FromMilliseconds(200));
        got.Should().BeEmpty("the PLC should stay silent");
    }

    /// <summary>Closes the host end; the session must end.</summary>
    public async Task CloseAsync()
    {
        await _hostEnd.DisposeAsync();
        await Session.WaitAsync(DefaultTimeout);
    }

    public async ValueTask DisposeAsync()
    {
        await _hostEnd.DisposeAsync();
        _stop.Cancel();
        await Session.WaitAsync(DefaultTimeout);
        await PlcEnd.DisposeAsync();
        await _pump.WaitAsync(DefaultTimeout);
        _stop.Dispose();
    }

    private async Task PumpAsync()
    {
        var buffer = new byte[512];
        try
        {
            while (true)
            {
                int n = await _hostEnd.ReadAsync(buffer);
                long now = Stopwatch.GetTimestamp();
                if (n == 0)
                {
                    break;
                }

                for (int i = 0; i < n; i++)
                {
                    _received.Writer.TryWrite((buffer[i], now));
                }
            }
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException or OperationCanceledException)
        {
            // The link was closed.
        }
        finally
        {
            _received.Writer.TryComplete();
        }
    }
}
