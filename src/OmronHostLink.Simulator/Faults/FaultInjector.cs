namespace OmronHostLink.Simulator.Faults;

/// <summary>Chooses the faults of each answer frame from a seeded generator. Thread-safe; one per <see cref="VirtualPlc"/>.</summary>
internal sealed class FaultInjector
{
    private readonly FaultOptions _options;
    private readonly Random _random;
    private readonly object _gate = new();

    public FaultInjector(FaultOptions options)
    {
        _options = options;
        _random = new Random(options.Seed);
    }

    public FaultCounters Counters { get; } = new();

    public TimeSpan LateBy => _options.LateBy;

    /// <summary>Plans the faults of one frame. The generator is drawn the same number of times whatever is chosen, so choices stay deterministic.</summary>
    public FaultPlan Plan(byte[] frame)
    {
        if (!_options.Any)
        {
            Counters.Count(FaultPlan.None);
            return FaultPlan.None;
        }

        FaultPlan plan;
        lock (_gate)
        {
            bool drop = _random.NextDouble() < _options.Drop;
            bool corrupt = _random.NextDouble() < _options.Corrupt;
            int corruptAt = _random.Next(1, Math.Max(2, BodyEnd(frame)));
            bool noise = _random.NextDouble() < _options.Noise;
            var noiseBytes = new byte[_random.Next(1, 9)];
            for (int i = 0; i < noiseBytes.Length; i++)
            {
                byte b;
                do
                {
                    b = (byte)_random.Next(0x00, 0x80);
                }
                while (b is (byte)'@' or (byte)'\r');
                noiseBytes[i] = b;
            }

            bool truncate = _random.NextDouble() < _options.Truncate;
            int truncateTo = _random.Next(1, Math.Max(2, frame.Length));
            bool late = _random.NextDouble() < _options.Late;
            bool echo = _random.NextDouble() < _options.Echo;

            // Drawn only when asked for, so the faults a seed gives without it stay the same.
            bool outOfTurn = _options.OutOfTurn > 0 && _random.NextDouble() < _options.OutOfTurn;
            plan = new FaultPlan
            {
                Drop = drop,
                CorruptAt = corrupt && BodyEnd(frame) > 1 ? corruptAt : -1,
                Noise = noise ? noiseBytes : null,
                TruncateTo = truncate && frame.Length > 1 ? truncateTo : -1,
                Late = late,
                OutOfTurn = outOfTurn,
                Echo = echo,
            };
        }

        Counters.Count(plan);
        return plan;
    }

    /// <summary>Where the FCS of a frame starts (characters before it may be corrupted, except the leading <c>@</c>).</summary>
    private static int BodyEnd(byte[] frame)
    {
        int end = frame.Length - 1;
        if (end > 0 && frame[end - 1] == (byte)'*')
        {
            end--;
        }

        return end - 2;
    }
}
