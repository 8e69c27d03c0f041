using System.Globalization;
using System.Text.Json;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>Counts per unit of what the monitor heard: exchanges by outcome and answer latencies.</summary>
internal sealed class LineStatistics
{
    private readonly SortedDictionary<int, UnitCounts> _units = new();

    /// <summary>Frames heard (bare CRs included), not counting bytes that do not frame.</summary>
    public long Frames { get; private set; }

    /// <summary>Bytes that did not frame.</summary>
    public long NoiseBytes { get; private set; }

    /// <summary>Frames no exchange explains.</summary>
    public long Strays { get; private set; }

    /// <summary>Exchanges, all units.</summary>
    public long Exchanges { get; private set; }

    public void Count(MonitorEvent e)
    {
        switch (e)
        {
            case MonitorEvent.Exchanged x:
                Exchanges++;
                Frames += x.Exchange.CommandFrames.Count + x.Exchange.AnswerFrames.Count;
                Unit(x.Exchange.Unit).Add(x.Exchange);
                break;
            case MonitorEvent.Stray s:
                Strays++;
                Frames++;
                break;
            case MonitorEvent.Noise n:
                NoiseBytes += n.Frame.Bytes.Length;
                break;
        }
    }

    /// <summary>The counts in lines for people.</summary>
    public IEnumerable<string> Lines(TimeSpan elapsed)
    {
        yield return $"After {Durations.Format(elapsed)}: {Exchanges} exchange{(Exchanges == 1 ? "" : "s")}, {Frames} frame{(Frames == 1 ? "" : "s")}, {Strays} stray frame{(Strays == 1 ? "" : "s")}, {NoiseBytes} byte{(NoiseBytes == 1 ? "" : "s")} that do not frame.";
        foreach ((int unit, UnitCounts c) in _units)
        {
            string latency = c.Answered == 0 ? "" : $"; latency mean {MonitoredExchange.Milliseconds(c.Mean)} ms, max {MonitoredExchange.Milliseconds(c.Max)} ms";
            yield return $"  {(unit < 0 ? "no unit (@**, or a unit number damaged beyond reading)" : "unit " + unit.ToString("D2", CultureInfo.InvariantCulture))}: {c.Exchanges} exchanges, {c.Ok} ok, {c.EndCodes} with an error end code, {c.Unanswered} unanswered, {c.Damaged} damaged{latency}";
        }
    }

    /// <summary>The counts as a JSON document: <c>{"summary":{…}}</c>.</summary>
    public void Write(Utf8JsonWriter j, TimeSpan elapsed)
    {
        j.WriteStartObject();
        j.WriteStartObject("summary");
        j.WriteNumber("seconds", Math.Round(elapsed.TotalSeconds, 3));
        j.WriteNumber("exchanges", Exchanges);
        j.WriteNumber("frames", Frames);
        j.WriteNumber("strayFrames", Strays);
        j.WriteNumber("noiseBytes", NoiseBytes);
        j.WriteStartArray("units");
        foreach ((int unit, UnitCounts c) in _units)
        {
            j.WriteStartObject();
            if (unit < 0)
            {
                j.WriteNull("unit");
            }
            else
            {
                j.WriteNumber("unit", unit);
            }

            j.WriteNumber("exchanges", c.Exchanges);
            j.WriteNumber("ok", c.Ok);
            j.WriteNumber("endCodes", c.EndCodes);
            j.WriteNumber("unanswered", c.Unanswered);
            j.WriteNumber("damaged", c.Damaged);
            if (c.Answered > 0)
            {
                j.WriteNumber("latencyMeanMs", Math.Round(c.Mean.TotalMilliseconds, 3));
                j.WriteNumber("latencyMaxMs", Math.Round(c.Max.TotalMilliseconds, 3));
            }

            j.WriteEndObject();
        }

        j.WriteEndArray();
        j.WriteEndObject();
        j.WriteEndObject();
    }

    private UnitCounts Unit(int unit)
    {
        if (!_units.TryGetValue(unit, out UnitCounts? counts))
        {
            counts = new UnitCounts();
            _units[unit] = counts;
        }

        return counts;
    }

    private sealed class UnitCounts
    {
        private TimeSpan _total;

        public long Exchanges { get; private set; }

        public long Ok { get; private set; }

        public long EndCodes { get; private set; }

        public long Unanswered { get; private set; }

        public long Damaged { get; private set; }

        public long Answered { get; private set; }

        public TimeSpan Max { get; private set; }

        public TimeSpan Mean => Answered == 0 ? TimeSpan.Zero : _total / Answered;

        public void Add(MonitoredExchange x)
        {
            Exchanges++;
            switch (x.Status)
            {
                case ExchangeStatus.Ok:
                case ExchangeStatus.NoAnswerExpected:
                    Ok++;
                    break;
                case ExchangeStatus.EndCode:
                    EndCodes++;
                    break;
                case ExchangeStatus.Unanswered:
                    Unanswered++;
                    break;
                default:
                    Damaged++;
                    break;
            }

            if (x.Latency is { } latency)
            {
                Answered++;
                _total += latency;
                Max = latency > Max ? latency : Max;
            }
        }
    }
}
