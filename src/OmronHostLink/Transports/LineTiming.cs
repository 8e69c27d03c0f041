namespace OmronHostLink.Transports;

/// <summary>
/// The character rate of the serial line the PLC sits on, from which every frame deadline is derived. Over a TCP
/// serial-device server this is the speed of the serial side.
/// </summary>
public sealed class LineTiming
{
    /// <summary>Omron's default line: 9600 bps, 1 start + 7 data + even parity + 2 stop bits.</summary>
    public static LineTiming Default { get; } = new(SerialLineSettings.DefaultBaudRate, new SerialLineSettings().BitsPerCharacter);

    /// <summary>Creates the timing.</summary>
    /// <param name="baudRate">Bits per second, 300-1,000,000.</param>
    /// <param name="bitsPerCharacter">1 start + data + parity + stop bits (7E2 = 11, 8N1 = 10), 7-12.</param>
    public LineTiming(int baudRate, int bitsPerCharacter)
    {
        Guard.InRange(baudRate, 300, 1_000_000);
        Guard.InRange(bitsPerCharacter, 7, 12);
        BaudRate = baudRate;
        BitsPerCharacter = bitsPerCharacter;
    }

    /// <summary>Bits per second.</summary>
    public int BaudRate { get; }

    /// <summary>Bits on the wire per character.</summary>
    public int BitsPerCharacter { get; }

    /// <summary>Time one character takes on the wire.</summary>
    public TimeSpan CharacterTime => TimeSpan.FromTicks(TimeSpan.TicksPerSecond * BitsPerCharacter / BaudRate);

    /// <summary>Time <paramref name="characters"/> take on the wire: characters × bits per character / baud.</summary>
    public TimeSpan WireTime(int characters) => TimeSpan.FromTicks((long)characters * TimeSpan.TicksPerSecond * BitsPerCharacter / BaudRate);

    /// <summary>
    /// The deadline for a frame: the characters still to cross the line (what was sent and the longest answer) at the
    /// line's character rate, plus <paramref name="turnaround"/>, the time the PLC may take to start answering.
    /// </summary>
    internal TimeSpan FrameDeadline(int charactersSent, int charactersExpected, TimeSpan turnaround)
        => WireTime(charactersSent + charactersExpected) + turnaround;

    /// <inheritdoc/>
    public override string ToString() => $"{BaudRate} bps, {BitsPerCharacter} bits/char";
}
