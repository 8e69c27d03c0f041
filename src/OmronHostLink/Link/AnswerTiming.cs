using Microsoft.Extensions.Logging;
using OmronHostLink.Protocol;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// Whether an answer frame could be the answer to the command just sent, judged by when it arrived. A C-mode answer
/// carries no address, so a late answer to an earlier command, delivered out of turn, has the shape of a later one;
/// its timing tells it apart:
/// <list type="bullet">
/// <item><b>Too early.</b> A frame of N characters that answers M characters sent cannot be complete before (M + N)
/// characters have crossed the line.</item>
/// <item><b>Late while out of turn.</b> After an exchange timed out with its command sent, its answer may still
/// come (<see cref="AnswerOwed"/>) until a frame nobody asked for is seen (<see cref="Settled(ReadOnlySpan{byte})"/>). Meanwhile, and
/// for as long after a frame nobody asked for (<see cref="MayBeOutOfTurn"/>), an answer
/// that comes later than the unit has lately been answering (its recent longest turnaround, two character times and
/// <see cref="LateMargin"/>) may be that answer standing in for one lost on the line.</item>
/// </list>
/// Both need the line's real speed: the checks are armed by the first TS fence whose echo (a fresh random token, so
/// certainly in step) came back no faster than the configured speed allows, and switched off for good, with one warning
/// naming the setting, by a fence echo that came back faster. An answer that comes too early is put to a TS check
/// before it is refused (<see cref="TransactionAttempt"/>): an echo that is itself too early shows the line runs faster
/// than configured, so a line configured slower than it runs costs no failures.
/// </summary>
/// <remarks>
/// Until a fence has run nothing can be stale: an answer only goes astray after an exchange failed, and every failed
/// exchange is followed by a fence. The tolerance covers a UART's clock error; a PLC's turnaround,
/// a USB adapter's latency and a serial-device server's network only ever make an answer later. A unit's turnaround is
/// learned from its answers and fence echoes as a decaying maximum, so a PLC whose scan grows is followed within a few
/// exchanges; an answer refused for lateness costs a retry, never a value. The tolerance is 2 % of the wire time.
/// </remarks>
internal sealed class AnswerTiming
{
    /// <summary>What an answer may exceed the unit's recent longest turnaround by (with two character times) before it counts as late.</summary>
    public static readonly TimeSpan LateMargin = TimeSpan.FromMilliseconds(5);

    /// <summary>
    /// The share of the wire time an answer may beat it by: the PLC's UART clock and a USB adapter's divided baud rate
    /// are within 1 % of nominal; the check allows twice that.
    /// </summary>
    private const double Tolerance = 0.02;

    /// <summary>Turnarounds a unit is seen with before lateness is judged.</summary>
    private const int LeastObservations = 4;

    /// <summary>
    /// How long an owed answer is waited for at least: an answer lost on the line never comes, so an owed answer is
    /// forgotten after this or twice the latest any owed answer has been seen to come, whichever is longer.
    /// </summary>
    public static readonly TimeSpan LeastOwedLifetime = TimeSpan.FromSeconds(5);

    /// <summary>
    /// The least wire time of a fence for its echo to arm the checks: 15 ms, a TS fence at up to 19,200 bps. On a faster
    /// line a busy host's scheduling delays are as long as the characters' time, so an echo that took the line's time
    /// proves nothing about the line's speed (a stream with no line at all, under load, looks just like it).
    /// </summary>
    public static readonly TimeSpan LeastJudgedWireTime = TimeSpan.FromMilliseconds(15);

    /// <summary>Owed answers remembered at most (the oldest go first).</summary>
    private const int MostOwed = 64;

    private readonly LineTiming _timing;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly List<(int Unit, long At)> _owed = new();
    private TimeSpan _latestSettled;
    private readonly string _link;
    // Indexed by unit: a frame's unit number is two decimal digits.
    private readonly long[] _recentTurnaround = new long[100];
    private readonly long[] _lastUnasked = new long[100];
    private readonly int[] _observations = new int[100];
    private bool _armed;
    private bool _fasterThanConfigured;
    private bool _untimed;

    public AnswerTiming(LineTiming timing, TimeProvider time, ILogger logger, string link)
    {
        _timing = timing;
        _time = time;
        _logger = logger;
        _link = link;
    }

    /// <summary>Whether answers are checked: a fence came back in plausible time and none faster.</summary>
    public bool Armed => _armed && !_fasterThanConfigured && !_untimed;

    /// <summary>Whether a fence came back faster than the configured speed allows.</summary>
    public bool FasterThanConfigured => _fasterThanConfigured;

    /// <summary>
    /// Answers of <paramref name="unit"/> to timed-out exchanges that may still come, less the frames of that unit nobody
    /// asked for seen since (each taken to be its oldest owed answer), less those owed longer than their lifetime
    /// (<see cref="LeastOwedLifetime"/>). Only a unit's own late answer can pass for its answer: another unit's carries
    /// its unit number.
    /// </summary>
    public int Owed(int unit)
    {
        if (_owed.Count == 0)
        {
            return 0;
        }

        TimeSpan lifetime = OwedLifetime;
        _owed.RemoveAll(o => _time.GetElapsedTime(o.At) >= lifetime);
        int count = 0;
        foreach ((int owedUnit, _) in _owed)
        {
            count += owedUnit == unit ? 1 : 0;
        }

        return count;
    }

    /// <summary>
    /// Whether an answer of <paramref name="unit"/> may be an earlier command's: one of its answers is owed, or within an
    /// owed answer's lifetime a frame of that unit came that nobody asked for. Answers out of turn come in runs (a line
    /// that held one answer back holds the next), and a late answer that arrives while the next command is outstanding
    /// comes in that command's time: only a TS behind it shows whether another frame follows.
    /// </summary>
    public bool MayBeOutOfTurn(int unit)
        => Owed(unit) > 0 || ((uint)unit < (uint)_lastUnasked.Length && _lastUnasked[unit] != 0 && _time.GetElapsedTime(_lastUnasked[unit]) < OwedLifetime);

    /// <summary>How long an owed answer is waited for: <see cref="LeastOwedLifetime"/>, or twice the latest one has come if longer.</summary>
    private TimeSpan OwedLifetime => _latestSettled + _latestSettled > LeastOwedLifetime ? _latestSettled + _latestSettled : LeastOwedLifetime;

    /// <summary>The least time <paramref name="characters"/> (both ways) can take on the line, tolerance taken off.</summary>
    public TimeSpan Earliest(int characters) => TimeSpan.FromTicks((long)(_timing.WireTime(characters).Ticks * (1 - Tolerance)));

    /// <summary>
    /// Whether a frame of <paramref name="received"/> characters, complete <paramref name="elapsed"/> after the start of
    /// a write of <paramref name="sent"/> characters, came too early to answer it.
    /// </summary>
    public bool IsTooEarly(TimeSpan elapsed, int sent, int received) => Armed && elapsed < Earliest(sent + received);

    /// <summary>
    /// Whether an answer from <paramref name="unit"/> came so late, while the unit may be out of turn
    /// (<see cref="MayBeOutOfTurn"/>), that it may be an earlier command's; if so, <paramref name="usual"/> is the latest
    /// the unit has lately been answering in.
    /// </summary>
    public bool IsLateWhileOwed(int unit, TimeSpan elapsed, int sent, int received, out TimeSpan usual)
    {
        usual = TimeSpan.Zero;
        if (!Armed || (uint)unit >= (uint)_observations.Length || _observations[unit] < LeastObservations || !MayBeOutOfTurn(unit))
        {
            return false;
        }

        usual = TimeSpan.FromTicks(_recentTurnaround[unit]) + LateMargin + _timing.WireTime(2);
        return elapsed - _timing.WireTime(sent + received) > usual;
    }

    /// <summary>Notes the turnaround of an answer (or fence echo) from <paramref name="unit"/> taken as in step.</summary>
    public void Answered(int unit, TimeSpan elapsed, int sent, int received)
    {
        if ((uint)unit >= (uint)_observations.Length)
        {
            return;
        }

        long turnaround = Math.Max(0, (elapsed - _timing.WireTime(sent + received)).Ticks);

        // A decaying maximum: a longer turnaround counts at once, a shorter one lowers the mark by a sixteenth a time.
        long mark = _recentTurnaround[unit];
        _recentTurnaround[unit] = turnaround >= mark ? turnaround : mark - ((mark - turnaround) / 16);
        _observations[unit]++;
    }

    /// <summary>An exchange with <paramref name="unit"/> timed out after its command was sent: its answer may still come, out of turn.</summary>
    public void AnswerOwed(int unit)
    {
        if (_owed.Count == MostOwed)
        {
            _owed.RemoveAt(0);
        }

        _owed.Add((unit, _time.GetTimestamp()));
    }

    /// <summary>
    /// A frame nobody asked for was seen (discarded, refused or out of turn): it may have been an owed answer. An intact
    /// one (its FCS right) also shows that the unit's line delivers out of turn (<see cref="MayBeOutOfTurn"/>); a damaged
    /// one may be noise or a damaged answer to the command outstanding.
    /// </summary>
    /// <param name="frame">The frame, or what is left of it; its unit number is read from <c>@</c> and two digits.</param>
    public void Settled(ReadOnlySpan<byte> frame)
    {
        if (frame.Length < 3 || frame[0] != (byte)'@' || !IsDigit(frame[1]) || !IsDigit(frame[2]))
        {
            return;
        }

        int unit = ((frame[1] - '0') * 10) + (frame[2] - '0');
        int end = frame.IndexOf((byte)'\r');
        if (end >= 0 && FrameCheck.Of(frame.Slice(0, end + 1)).FcsMatches)
        {
            Settled(unit);
        }
        else
        {
            SettleOwed(unit);
        }
    }

    /// <summary>An intact frame of <paramref name="unit"/> nobody asked for was seen, or its answer was refused as a late one: it may have been an owed answer, and the unit's line delivers out of turn.</summary>
    public void Settled(int unit)
    {
        if ((uint)unit < (uint)_lastUnasked.Length)
        {
            _lastUnasked[unit] = _time.GetTimestamp();
        }

        SettleOwed(unit);
    }

    /// <summary>Takes a frame of <paramref name="unit"/> as its oldest owed answer, if one is owed.</summary>
    private void SettleOwed(int unit)
    {
        int oldest = _owed.FindIndex(o => o.Unit == unit);
        if (oldest >= 0)
        {
            TimeSpan late = _time.GetElapsedTime(_owed[oldest].At);
            _latestSettled = late > _latestSettled ? late : _latestSettled;
            _owed.RemoveAt(oldest);
        }
    }

    /// <summary>Settles every frame that starts in <paramref name="bytes"/> (bytes discarded at once).</summary>
    public void SettledAll(ReadOnlySpan<byte> bytes)
    {
        while (bytes.IndexOf((byte)'@') is int at and >= 0)
        {
            Settled(bytes.Slice(at));
            bytes = bytes.Slice(at + 1);
        }
    }

    private static bool IsDigit(byte b) => b is >= (byte)'0' and <= (byte)'9';

    /// <summary>The transport was opened anew: nothing sent on the old one can arrive on it.</summary>
    /// <param name="timed">
    /// False for a pseudo-terminal, which carries bytes at no line speed at all (whatever speed the port is set to):
    /// answers on it are not judged by time.
    /// </param>
    public void Reopened(bool timed)
    {
        _owed.Clear();
        Array.Clear(_lastUnasked, 0, _lastUnasked.Length);
        _untimed = !timed;
    }

    /// <summary>Takes a fence's echo, certainly in step, as a measure of the line: it arms the checks or, if too fast, ends them.</summary>
    /// <returns>Whether the echo took at least the configured line's time: the configured speed stands.</returns>
    public bool FenceEchoed(int unit, TimeSpan elapsed, int sent, int received)
    {
        TimeSpan earliest = Earliest(sent + received);
        if (elapsed >= earliest)
        {
            _armed |= _timing.WireTime(sent + received) >= LeastJudgedWireTime;
            Answered(unit, elapsed, sent, received);
            return true;
        }

        if (!_fasterThanConfigured)
        {
            _fasterThanConfigured = true;
            HostLinkLog.FasterThanConfigured(_logger, _link, elapsed.TotalMilliseconds, _timing.BaudRate, earliest.TotalMilliseconds);
        }

        return false;
    }
}
