using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Detection;

/// <summary>A character format as people write it: data bits, parity letter, stop bits (<c>7E2</c>, <c>8N1</c>).</summary>
internal readonly record struct LineFormat(int DataBits, SerialParity Parity, SerialStopBits StopBits)
{
    /// <summary>Omron's default: 7 data bits, even parity, 2 stop bits.</summary>
    public static readonly LineFormat OmronDefault = new(7, SerialParity.Even, SerialStopBits.Two);

    /// <summary>
    /// The formats <c>detect</c> tries, likeliest first: one of each pair a receiver cannot tell apart (7E2 and 7E1
    /// differ only in the stop bits, which a UART does not check beyond the first).
    /// </summary>
    public static readonly LineFormat[] Usual =
    [
        OmronDefault,
        new(8, SerialParity.None, SerialStopBits.One),
        new(7, SerialParity.Odd, SerialStopBits.Two),
        new(8, SerialParity.Even, SerialStopBits.One),
        new(8, SerialParity.Odd, SerialStopBits.One),
        new(7, SerialParity.None, SerialStopBits.Two),
    ];

    /// <summary>The format of <paramref name="settings"/>.</summary>
    public static LineFormat Of(SerialLineSettings settings) => new(settings.DataBits, settings.Parity, settings.StopBits);

    /// <summary>Parses <c>7E2</c>, <c>8n1</c> and the like.</summary>
    public static bool TryParse(string text, out LineFormat format)
    {
        format = default;
        string t = text.Trim();
        if (t.Length != 3 || t[0] is not ('7' or '8') || t[2] is not ('1' or '2'))
        {
            return false;
        }

        SerialParity? parity = char.ToUpperInvariant(t[1]) switch
        {
            'E' => SerialParity.Even,
            'O' => SerialParity.Odd,
            'N' => SerialParity.None,
            _ => null,
        };
        if (parity is null)
        {
            return false;
        }

        format = new LineFormat(t[0] - '0', parity.Value, t[2] == '1' ? SerialStopBits.One : SerialStopBits.Two);
        return true;
    }

    /// <summary>The parity as a letter: E, O or N.</summary>
    public char ParityLetter => Parity switch
    {
        SerialParity.Even => 'E',
        SerialParity.Odd => 'O',
        _ => 'N',
    };

    /// <summary>The same format with the other number of stop bits: a receiver cannot tell the two apart.</summary>
    public LineFormat OtherStopBits => this with { StopBits = StopBits == SerialStopBits.One ? SerialStopBits.Two : SerialStopBits.One };

    /// <summary>Whether a receiver set to one takes what a transmitter set to the other sends (same data bits and parity).</summary>
    public bool SameOnTheWire(LineFormat other) => DataBits == other.DataBits && Parity == other.Parity;

    /// <summary>The settings of port <paramref name="port"/> at <paramref name="baud"/> in this format.</summary>
    public SerialLineSettings At(string port, int baud) => new()
    {
        PortName = port,
        BaudRate = baud,
        DataBits = DataBits,
        Parity = Parity,
        StopBits = StopBits,
    };

    /// <summary>In words: "7 data bits, even parity, 2 stop bits".</summary>
    public string Words => $"{DataBits} data bits, {Parity switch { SerialParity.Even => "even parity", SerialParity.Odd => "odd parity", _ => "no parity" }}, {(int)StopBits} stop bit{(StopBits == SerialStopBits.One ? "" : "s")}";

    /// <inheritdoc/>
    public override string ToString() => $"{DataBits}{ParityLetter}{(int)StopBits}";
}
