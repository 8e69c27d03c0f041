using System.Diagnostics;
using System.Text;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Benchmarks.Polling;

/// <summary>
/// The PLC's end of an emulated line, watched: every C-mode command the PLC receives is decoded (area reads, QQMR's
/// registration and the QQIR that reads it, RG's completion flags) and each memory word it reads is stamped with the
/// time the command arrived, so that each tag's refresh is measured where it happens, whichever gateway polls. Also
/// counts commands by header and times the line's busy bursts (from a command's first character to the end of the last
/// answer before the line falls quiet).
/// </summary>
internal sealed class CommandTap(Stream inner, CommandLedger ledger) : PassThroughStream(inner)
{
    private readonly StringBuilder _frame = new();
    private readonly StringBuilder _command = new();

    public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
    {
        int n = await Inner.ReadAsync(buffer, cancellationToken).ConfigureAwait(false);
        long now = Stopwatch.GetTimestamp();
        for (int i = 0; i < n; i++)
        {
            char c = (char)buffer.Span[i];
            if (c != '\r')
            {
                _frame.Append(c);
                continue;
            }

            Frame(_frame.ToString(), now, _frame.Length + 1);
            _frame.Clear();
        }

        if (n > 0)
        {
            // The characters arrived at the line's pace: they were on the line for the time they take.
            ledger.Busy(now - ledger.LineTicks(n), now);
        }

        return n;
    }

    public override async ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
    {
        long start = Stopwatch.GetTimestamp();
        await Inner.WriteAsync(buffer, cancellationToken).ConfigureAwait(false);
        ledger.Busy(start, Stopwatch.GetTimestamp(), answer: true);
    }

    private void Frame(string frame, long now, int characters)
    {
        if (frame.Length == 0)
        {
            return; // the host asking for the next frame of an answer
        }

        if (frame[0] == '@')
        {
            _command.Clear();
            frame = frame[1..];
        }

        bool last = frame.EndsWith('*');
        _command.Append(frame, 0, Math.Max(0, frame.Length - (last ? 3 : 2))); // less the FCS (and the terminator)
        if (last)
        {
            ledger.Command(_command.ToString(), now, now - ledger.LineTicks(characters));
        }
    }
}

/// <summary>What one line's PLC was asked, by command and by word.</summary>
/// <param name="ticksPerCharacter">A character's time on the line, in Stopwatch ticks.</param>
/// <param name="quiet">How long the line must rest for a busy burst to end.</param>
/// <param name="keepTimes">Keep every read's time (for windows measured after the run); false keeps only running figures, in constant memory.</param>
/// <param name="classify">Names the scan class a word belongs to, so each command's time on the line is counted to its class; null for none.</param>
internal sealed class CommandLedger(double ticksPerCharacter, TimeSpan quiet, bool keepTimes = true, Func<CommandLedger.ReadKey, string?>? classify = null)
{
    private readonly object _gate = new();
    private readonly Dictionary<string, long> _headers = new(StringComparer.Ordinal);
    private readonly Dictionary<ReadKey, List<long>> _reads = new();
    private readonly Dictionary<ReadKey, KeyStats> _stats = new();
    private readonly Dictionary<string, (long Commands, long Ticks)> _classes = new(StringComparer.Ordinal);
    private readonly Dictionary<int, CompoundItem[]> _registered = new();
    private readonly List<(long Start, long End)> _bursts = new();
    private long _burstStart;
    private long _lastActivity;
    private (string Class, long Start)? _open;
    private long _lastWriteEnd;
    private long _pendingStart;

    /// <summary>The running figures of one word's reads: how many, the first and last, and the longest gap between two.</summary>
    public sealed class KeyStats
    {
        public long Count { get; set; }

        public long First { get; set; }

        public long Last { get; set; }

        public long MaxGap { get; set; }

        /// <summary>The mean time between reads, in seconds; infinity when read less than twice.</summary>
        public double MeanSeconds => Count < 2 ? double.PositiveInfinity : (Last - First) / (double)Stopwatch.Frequency / (Count - 1);
    }

    /// <summary>A word's running figures since the last <see cref="ResetStats"/>; null when not read.</summary>
    public KeyStats? StatsOf(ReadKey key)
    {
        lock (_gate)
        {
            return _stats.TryGetValue(key, out KeyStats? stats) ? new KeyStats { Count = stats.Count, First = stats.First, Last = stats.Last, MaxGap = stats.MaxGap } : null;
        }
    }

    /// <summary>Per scan class, the commands and their time on the line (command in to last answer frame out), since the last <see cref="ResetStats"/>.</summary>
    public IReadOnlyDictionary<string, (long Commands, long Ticks)> Classes
    {
        get
        {
            lock (_gate)
            {
                return new Dictionary<string, (long, long)>(_classes);
            }
        }
    }

    /// <summary>Starts the running figures again (a measured window).</summary>
    public void ResetStats()
    {
        lock (_gate)
        {
            _stats.Clear();
            _classes.Clear();
            _headers.Clear();
        }
    }

    /// <summary>A word read, a timer/counter's present value (<see cref="Flag"/> false) or its completion flag (true).</summary>
    public readonly record struct ReadKey(int Unit, PlcArea Area, int Bank, int Word, bool Flag);

    /// <summary>Commands received, by header (QQ counts QQMR and QQIR together).</summary>
    public IReadOnlyDictionary<string, long> Headers
    {
        get
        {
            lock (_gate)
            {
                return new Dictionary<string, long>(_headers);
            }
        }
    }

    /// <summary>Every command received.</summary>
    public long Commands
    {
        get
        {
            lock (_gate)
            {
                return _headers.Values.Sum();
            }
        }
    }

    /// <summary>The times (Stopwatch ticks) the commands reading <paramref name="key"/> arrived.</summary>
    public long[] ReadTimes(ReadKey key)
    {
        lock (_gate)
        {
            return _reads.TryGetValue(key, out List<long>? times) ? [.. times] : [];
        }
    }

    /// <summary>The line's busy bursts that ended between <paramref name="from"/> and <paramref name="to"/>, in ms.</summary>
    public double[] BurstsMs(long from, long to)
    {
        lock (_gate)
        {
            return _bursts.Where(b => b.Start >= from && b.End <= to).Select(b => (b.End - b.Start) * 1000.0 / Stopwatch.Frequency).ToArray();
        }
    }

    /// <summary>The time <paramref name="characters"/> take on the line, in Stopwatch ticks.</summary>
    public long LineTicks(int characters) => (long)(characters * ticksPerCharacter);

    /// <summary>The line carried characters from <paramref name="start"/> to <paramref name="end"/>.</summary>
    public void Busy(long start, long end, bool answer = false)
    {
        lock (_gate)
        {
            if (answer)
            {
                _lastWriteEnd = end;
            }

            // Quiet for long enough: a burst ended at the last activity.
            if (_burstStart != 0 && start - _lastActivity > quiet.TotalSeconds * Stopwatch.Frequency)
            {
                if (keepTimes)
                {
                    _bursts.Add((_burstStart, _lastActivity));
                }

                _burstStart = 0;
            }

            if (_burstStart == 0)
            {
                _burstStart = start;
            }

            _lastActivity = Math.Max(_lastActivity, end);
        }
    }

    public void Command(string text, long now, long start = 0)
    {
        if (text.Length < 4)
        {
            return;
        }

        lock (_gate)
        {
            // The command before ended with its last answer frame: its time on the line goes to its class.
            if (_open is { } open && _lastWriteEnd > open.Start)
            {
                (long c, long t) = _classes.GetValueOrDefault(open.Class);
                _classes[open.Class] = (c + 1, t + (_lastWriteEnd - open.Start));
            }

            _open = null;
            _pendingStart = start == 0 ? now : start;
        }

        int unit = int.Parse(text.AsSpan(0, 2), System.Globalization.CultureInfo.InvariantCulture);
        string header = text.Substring(2, 2);
        byte[] body = Encoding.ASCII.GetBytes(text[4..]);
        lock (_gate)
        {
            _headers[header] = _headers.GetValueOrDefault(header) + 1;
            CModeCommand command;
            try
            {
                command = CModeCommandParser.Parse(CModeCommandTable.Standard, Encoding.ASCII.GetBytes(header), body);
            }
            catch (Exception e) when (e is ArgumentException or FormatException or CModeCommandRejectedException)
            {
                return;
            }

            switch (command)
            {
                case AreaReadCommand read:
                    for (int i = 0; i < read.Count; i++)
                    {
                        (PlcArea area, int word) = OmronHostLink.CModeAddressing.Locate(read.Area, read.Begin + i);
                        Stamp(new ReadKey(unit, area, read.Area == CModeArea.Em ? read.Bank : 0, word, read.Area == CModeArea.TimerCounterStatus), now);
                    }

                    break;
                case CompoundRegisterCommand register:
                    _registered[unit] = [.. register.Items];
                    break;
                default:
                    if (header == "QQ" && _registered.TryGetValue(unit, out CompoundItem[]? items))
                    {
                        foreach (CompoundItem item in items)
                        {
                            (PlcArea area, int word, int bank) = item.Locate();
                            Stamp(new ReadKey(unit, area, bank, word, false), now);
                            if (item.IsTimerCounterWord)
                            {
                                Stamp(new ReadKey(unit, area, bank, word, true), now);
                            }
                        }
                    }

                    break;
            }
        }
    }

    private void Stamp(ReadKey key, long now)
    {
        if (_open is null && classify?.Invoke(key) is { } scanClass)
        {
            _open = (scanClass, _pendingStart);
        }

        if (!_stats.TryGetValue(key, out KeyStats? stats))
        {
            _stats[key] = stats = new KeyStats { First = now };
        }
        else
        {
            stats.MaxGap = Math.Max(stats.MaxGap, now - stats.Last);
        }

        stats.Count++;
        stats.Last = now;
        if (!keepTimes)
        {
            return;
        }

        if (!_reads.TryGetValue(key, out List<long>? times))
        {
            _reads[key] = times = new List<long>();
        }

        times.Add(now);
    }
}
