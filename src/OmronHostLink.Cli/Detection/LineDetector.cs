using System.Diagnostics;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Detection;

/// <summary>
/// Finds a serial line's speed and format by sending TS (TEST) at each in turn and reading what comes back: TS echoes its
/// text in any PLC mode and changes nothing, so it is the one safe probe. Each try opens the port at its settings, sends
/// one short TS, reads until a unit has answered or the try's deadline (the frame's wire time three times over, for an
/// echo, a turnaround and the answer, plus the turnaround allowance), and closes the port.
/// </summary>
/// <remarks>
/// A PLC's TS answer is the very characters sent, and so is the echo of a 2-wire RS-485 adapter. A copy that comes back
/// while the echo is not known yet is checked by one more try at the same speed in a format no PLC port could take at
/// the same time (7 data bits and parity against 8 and none): a copy there too is the line's echo, which then comes back
/// at every setting, and from then on only a second copy counts as an answer.
/// </remarks>
internal sealed class LineDetector
{
    private const int TokenLength = 4;

    private readonly Func<SerialLineSettings, IHostLinkTransport> _open;
    private readonly TimeSpan _turnaround;
    private readonly string _port;

    public LineDetector(Func<SerialLineSettings, IHostLinkTransport> open, string port, TimeSpan turnaround)
    {
        _open = open;
        _port = port;
        _turnaround = turnaround;
    }

    /// <summary>What the search found.</summary>
    internal sealed record Outcome(IReadOnlyList<ProbeTry> Tries, ProbeTry? Found, bool? Echo, TimeSpan Elapsed);

    /// <summary>
    /// Tries each of <paramref name="candidates"/> in order with a TS to each of <paramref name="units"/> until a unit
    /// answers; <paramref name="report"/> is told of each try as it ends.
    /// </summary>
    /// <exception cref="HostLinkConnectionException">The port cannot be opened at all.</exception>
    public async Task<Outcome> SearchAsync(IReadOnlyList<(int Baud, LineFormat Format)> candidates, IReadOnlyList<int> units, Action<ProbeTry> report, CancellationToken cancellationToken)
    {
        var clock = Stopwatch.StartNew();
        var tries = new List<ProbeTry>();
        var confirmed = new HashSet<(int Baud, int DataBits, Transports.SerialParity Parity, int Unit)>();
        bool? echo = null;
        foreach ((int baud, LineFormat format) in candidates)
        {
            foreach (int unit in units)
            {
                if (confirmed.Contains((baud, format.DataBits, format.Parity, unit)))
                {
                    // Tried already, to learn that the line echoes: only the echo came back there.
                    continue;
                }

                ProbeTry probe = await TryAsync(baud, format, unit, echo, confirming: false, cancellationToken).ConfigureAwait(false);
                tries.Add(probe);
                report(probe);
                ProbeReply reply = probe.Reply;
                if (echo is null && reply.Copies >= 2)
                {
                    // The echo and the answer.
                    return new Outcome(tries, probe, true, clock.Elapsed);
                }

                if (echo is null && reply.Copies == 1 && reply.EndCode is null && !reply.Ic)
                {
                    // An answer, or only the echo: a format no PLC could answer at the same time as this one tells.
                    LineFormat contrast = format.DataBits == 7 ? new LineFormat(8, SerialParity.None, SerialStopBits.One) : LineFormat.OmronDefault;
                    ProbeTry check = await TryAsync(baud, contrast, unit, echo, confirming: true, cancellationToken).ConfigureAwait(false);
                    tries.Add(check);
                    report(check);
                    confirmed.Add((baud, contrast.DataBits, contrast.Parity, unit));
                    if (check.Reply.Copies == 0)
                    {
                        return new Outcome(tries, probe, false, clock.Elapsed);
                    }

                    echo = true;
                    continue;
                }

                if (echo is null && reply.Copies == 0 && (reply.EndCode is not null || reply.Ic))
                {
                    return new Outcome(tries, probe, false, clock.Elapsed);
                }

                if (echo is not null && reply.Answered(echo.Value))
                {
                    return new Outcome(tries, probe, echo, clock.Elapsed);
                }
            }
        }

        return new Outcome(tries, null, echo, clock.Elapsed);
    }

    /// <summary>One try: opens the port at the settings, sends a TS to <paramref name="unit"/>, reads until answered or the deadline, closes the port.</summary>
    public async Task<ProbeTry> TryAsync(int baud, LineFormat format, int unit, bool? echo, bool confirming, CancellationToken cancellationToken)
    {
        SerialLineSettings settings = format.At(_port, baud);
        byte[] frame = TestFrame(unit);
        IHostLinkTransport transport = _open(settings);
        LineTiming timing = transport.LineTiming ?? new LineTiming(settings.BaudRate, settings.BitsPerCharacter);
        TimeSpan deadline = timing.WireTime(3 * frame.Length) + _turnaround;
        var received = new List<byte>();
        var clock = new Stopwatch();
        TimeSpan? answeredAt = null;
        TimeSpan? firstCopy = null;
        ProbeReply reply = ProbeReply.Of(frame, []);
        Task<int>? read = null;
        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        try
        {
            Stream stream = await transport.OpenAsync(cancellationToken).ConfigureAwait(false);
            clock.Start();
            await stream.WriteAsync(frame, cancellationToken).ConfigureAwait(false);
            await stream.FlushAsync(cancellationToken).ConfigureAwait(false);
            var buffer = new byte[512];
            while (true)
            {
                TimeSpan left = deadline - clock.Elapsed;
                if (left <= TimeSpan.Zero)
                {
                    break;
                }

                read ??= stream.ReadAsync(buffer, stop.Token).AsTask();
                if (await Task.WhenAny(read, Task.Delay(left, cancellationToken)).ConfigureAwait(false) != read)
                {
                    cancellationToken.ThrowIfCancellationRequested();
                    break;
                }

                int n;
                try
                {
                    n = await read.ConfigureAwait(false);
                }
                catch (Exception e) when (e is IOException or ObjectDisposedException or OperationCanceledException && !cancellationToken.IsCancellationRequested)
                {
                    break;
                }

                read = null;
                if (n == 0)
                {
                    break;
                }

                received.AddRange(buffer.AsSpan(0, n));
                reply = ProbeReply.Of(frame, received.ToArray());
                if (reply.Copies > 0)
                {
                    firstCopy ??= clock.Elapsed;
                }

                // With the echo not known yet, one copy may be either: wait for a second until the deadline.
                if (echo is null ? reply.Copies >= 2 || reply.EndCode is not null || reply.Ic : reply.Answered(echo.Value))
                {
                    answeredAt = clock.Elapsed;
                    break;
                }
            }
        }
        finally
        {
            stop.Cancel();

            // Closing the port ends a read still pending on it, on every platform.
            await transport.DisposeAsync().ConfigureAwait(false);
            if (read is not null)
            {
                try
                {
                    await read.ConfigureAwait(false);
                }
                catch (Exception e) when (e is IOException or ObjectDisposedException or OperationCanceledException or InvalidOperationException)
                {
                }
            }
        }

        return new ProbeTry(baud, format, unit, frame, reply, clock.Elapsed, answeredAt ?? (echo is null ? firstCopy : null), confirming);
    }

    /// <summary>A TS frame to <paramref name="unit"/> with a fresh random token of hex digits.</summary>
    internal static byte[] TestFrame(int unit)
    {
        Span<byte> token = stackalloc byte[TokenLength];
        for (int i = 0; i < token.Length; i++)
        {
            token[i] = HexAscii.Nibble(Random.Shared.Next(16));
        }

        var frame = new byte[CModeCommand.PrefixLength + TokenLength + FrameWriter.FinalOverhead];
        int length = TestCommand.WriteMessage(unit, token, frame);
        length = FrameWriter.WriteFrame(frame.AsSpan(0, length), final: true, frame);
        return frame.AsSpan(0, length).ToArray();
    }
}
