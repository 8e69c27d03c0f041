namespace OmronHostLink.Simulator.Faults;

/// <summary>
/// Faults the simulator injects into its answers, each with a probability per answer frame (0 = never, 1 = always).
/// The random choices come from a generator seeded with <see cref="Seed"/>, so a given seed and the same sequence of
/// commands give the same faults. The bare CR the PLC sends between the frames of a multi-frame command is never
/// faulted.
/// </summary>
public sealed class FaultOptions
{
    /// <summary>The seed of the random generator. Default 1.</summary>
    public int Seed { get; set; } = 1;

    /// <summary>Probability of sending no answer at all.</summary>
    public double Drop { get; set; }

    /// <summary>Probability of changing one character between the unit number and the FCS, so the FCS no longer matches.</summary>
    public double Corrupt { get; set; }

    /// <summary>Probability of sending 1-8 noise bytes (never <c>@</c> or CR) before the frame.</summary>
    public double Noise { get; set; }

    /// <summary>Probability of cutting the frame short: its CR (and possibly more) is never sent.</summary>
    public double Truncate { get; set; }

    /// <summary>Probability of answering late, <see cref="LateBy"/> after the answer was due (after the host's deadline).</summary>
    public double Late { get; set; }

    /// <summary>
    /// Probability of delivering the answer out of turn: it is held back <see cref="LateBy"/> while the PLC goes on
    /// answering later commands, then sent between them, as radio modems, protocol converters and buffering
    /// serial-device servers do. A host that cannot tell it from the answer to a later command of the same shape takes
    /// another command's data.
    /// </summary>
    public double OutOfTurn { get; set; }

    /// <summary>How late a late (or out-of-turn) answer comes. Default one second.</summary>
    public TimeSpan LateBy { get; set; } = TimeSpan.FromSeconds(1);

    /// <summary>Probability of echoing the received frame back before the answer, as a 2-wire RS-485 line does.</summary>
    public double Echo { get; set; }

    /// <summary>Whether any fault may happen.</summary>
    public bool Any => Drop > 0 || Corrupt > 0 || Noise > 0 || Truncate > 0 || Late > 0 || OutOfTurn > 0 || Echo > 0;

    /// <summary>Checks the options.</summary>
    /// <exception cref="ArgumentException">A probability is outside 0-1, or <see cref="LateBy"/> is negative.</exception>
    public void Validate()
    {
        Check(Drop, nameof(Drop));
        Check(Corrupt, nameof(Corrupt));
        Check(Noise, nameof(Noise));
        Check(Truncate, nameof(Truncate));
        Check(Late, nameof(Late));
        Check(OutOfTurn, nameof(OutOfTurn));
        Check(Echo, nameof(Echo));
        if (LateBy < TimeSpan.Zero)
        {
            throw new ArgumentException("LateBy cannot be negative.", nameof(LateBy));
        }
    }

    private static void Check(double p, string name)
    {
        if (double.IsNaN(p) || p < 0 || p > 1)
        {
            throw new ArgumentException($"The probability {name} must be 0-1; it was {p}.", name);
        }
    }
}
