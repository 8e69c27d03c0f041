using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Simulator;

/// <summary>
/// A multidrop Host Link line with several <see cref="VirtualPlc"/>s on it, each answering its own unit numbers with
/// its own memory, mode and errors (a single <see cref="VirtualPlc"/> with several units is one CPU answering to all of
/// them). Each answer is shaped by the PLC that gives it (its turnaround and faults); the line's speed is shared.
/// </summary>
public sealed class VirtualPlcLine
{
    private readonly Dictionary<int, VirtualPlc> _byUnit = new();

    /// <summary>Puts the PLCs on one line.</summary>
    /// <param name="plcs">The PLCs; their unit numbers must be distinct and their <see cref="VirtualPlcOptions.BaudRate"/> and <see cref="VirtualPlcOptions.BitsPerCharacter"/> the same.</param>
    /// <exception cref="ArgumentException">No PLC, a unit number answered by two PLCs, or different line speeds.</exception>
    public VirtualPlcLine(IEnumerable<VirtualPlc> plcs)
    {
        ArgumentNullException.ThrowIfNull(plcs);
        Plcs = plcs.ToArray();
        if (Plcs.Count == 0)
        {
            throw new ArgumentException("A line needs at least one PLC.", nameof(plcs));
        }

        VirtualPlcOptions first = Plcs[0].Options;
        foreach (VirtualPlc plc in Plcs)
        {
            if (plc.Options.BaudRate != first.BaudRate || plc.Options.BitsPerCharacter != first.BitsPerCharacter)
            {
                throw new ArgumentException("The PLCs of one line share its speed: BaudRate and BitsPerCharacter must be the same for all.", nameof(plcs));
            }

            foreach (int unit in plc.Options.Units)
            {
                if (!_byUnit.TryAdd(unit, plc) && !ReferenceEquals(_byUnit[unit], plc))
                {
                    throw new ArgumentException($"Unit {unit:D2} is answered by two PLCs on the line.", nameof(plcs));
                }
            }
        }
    }

    /// <summary>The PLCs on the line.</summary>
    public IReadOnlyList<VirtualPlc> Plcs { get; }

    /// <summary>The unit numbers answered on the line, in order.</summary>
    public IReadOnlyList<int> Units => _byUnit.Keys.Order().ToArray();

    /// <summary>The PLC that answers <paramref name="unit"/>.</summary>
    /// <exception cref="KeyNotFoundException">No PLC on the line answers that unit number.</exception>
    public VirtualPlc this[int unit] => _byUnit.TryGetValue(unit, out VirtualPlc? plc)
        ? plc
        : throw new KeyNotFoundException($"No PLC on the line answers unit {unit:D2}.");

    /// <summary>One PLC per unit number, each created from a copy of <paramref name="options"/> with that one unit.</summary>
    /// <param name="options">The options every PLC starts from; <see cref="VirtualPlcOptions.Units"/> lists the units.</param>
    /// <returns>The line.</returns>
    /// <exception cref="ArgumentException">The options are not valid.</exception>
    public static VirtualPlcLine OnePlcPerUnit(VirtualPlcOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        options.Validate();
        return new VirtualPlcLine(options.Units.Distinct().Select(unit => new VirtualPlc(options.WithUnits([unit]))));
    }

    /// <summary>Serves one Host Link session of every PLC on the line over <paramref name="stream"/> (see <see cref="VirtualPlc.RunAsync"/>).</summary>
    /// <param name="stream">The stream; the PLCs read commands from it and write answers to it.</param>
    /// <param name="cancellationToken">Ends the session.</param>
    /// <returns>A task that completes when the session ends.</returns>
    public Task RunAsync(Stream stream, CancellationToken cancellationToken = default)
        => new HostLinkSession(Plcs).RunAsync(stream, cancellationToken);
}
