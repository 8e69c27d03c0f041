using System.Globalization;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// CPU time and resident memory of a process from <c>/proc/&lt;pid&gt;/stat</c> and <c>/proc/&lt;pid&gt;/status</c>
/// (Linux): CPU % over an interval = Δ(utime + stime) / clock ticks per second / elapsed seconds, 100 % = one core.
/// </summary>
internal readonly record struct ProcessSample(long CpuTicks, long RssKilobytes)
{
    private static readonly Lazy<long> TicksPerSecond = new(ReadTicksPerSecond);

    /// <summary>Clock ticks per second of utime/stime (<c>getconf CLK_TCK</c>; 100 on Linux unless it says otherwise).</summary>
    public static long ClockTicksPerSecond => TicksPerSecond.Value;

    /// <summary>Reads the process's counters; null once it has gone.</summary>
    public static ProcessSample? Read(int pid)
    {
        try
        {
            string stat = File.ReadAllText($"/proc/{pid}/stat");
            // The command name (field 2) is in parentheses and may hold spaces: count fields after the last ')'.
            string[] fields = stat[(stat.LastIndexOf(')') + 2)..].Split(' ');
            long utime = long.Parse(fields[11], CultureInfo.InvariantCulture); // field 14
            long stime = long.Parse(fields[12], CultureInfo.InvariantCulture); // field 15
            long rss = 0;
            foreach (string line in File.ReadLines($"/proc/{pid}/status"))
            {
                if (line.StartsWith("VmRSS:", StringComparison.Ordinal))
                {
                    rss = long.Parse(line["VmRSS:".Length..].Trim().Split(' ')[0], CultureInfo.InvariantCulture);
                    break;
                }
            }

            return new ProcessSample(utime + stime, rss);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or FormatException or IndexOutOfRangeException)
        {
            return null;
        }
    }

    /// <summary>CPU % of one core between <paramref name="start"/> and this sample, <paramref name="seconds"/> apart.</summary>
    public double CpuPercentSince(ProcessSample start, double seconds)
        => (CpuTicks - start.CpuTicks) * 100.0 / ClockTicksPerSecond / seconds;

    /// <summary>The 1-minute load average now.</summary>
    public static double LoadAverage()
    {
        try
        {
            return double.Parse(File.ReadAllText("/proc/loadavg").Split(' ')[0], CultureInfo.InvariantCulture);
        }
        catch (Exception e) when (e is IOException or FormatException)
        {
            return double.NaN;
        }
    }

    private static long ReadTicksPerSecond()
    {
        try
        {
            using var getconf = System.Diagnostics.Process.Start(new System.Diagnostics.ProcessStartInfo("getconf", "CLK_TCK") { RedirectStandardOutput = true, UseShellExecute = false })!;
            string text = getconf.StandardOutput.ReadToEnd();
            getconf.WaitForExit(5000);
            return long.TryParse(text.Trim(), NumberStyles.Integer, CultureInfo.InvariantCulture, out long ticks) && ticks > 0 ? ticks : 100;
        }
        catch (System.ComponentModel.Win32Exception)
        {
            return 100;
        }
    }
}
