using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// The serial line of a Host Link client. With <see cref="PortName"/>, a serial port on this machine; with
/// <see cref="HostLinkClientSettings.Tcp"/> instead, the line behind the serial-device server, whose
/// <see cref="BaudRate"/>, <see cref="DataBits"/>, <see cref="Parity"/> and <see cref="StopBits"/> set the frame
/// deadlines (the server's own port settings must match them). Unset values take Omron's defaults: 9600 7E2.
/// </summary>
public sealed class HostLinkSerialSettings : HostLinkEndpointSettings
{
    private static readonly SettingKeys<HostLinkSerialSettings> Keys = new("a serial line setting")
    {
        { nameof(PortName), (v, s) => s.PortName = v.Text() ?? s.PortName },
        { nameof(BaudRate), (v, s) => s.BaudRate = v.Integer() ?? s.BaudRate },
        { nameof(DataBits), (v, s) => s.DataBits = v.Integer() ?? s.DataBits },
        { nameof(Parity), (v, s) => s.Parity = v.Choice<SerialParity>() ?? s.Parity },
        { nameof(StopBits), (v, s) => s.StopBits = v.Choice(("1", SerialStopBits.One), ("2", SerialStopBits.Two)) ?? s.StopBits },
        { nameof(Handshake), (v, s) => s.Handshake = v.Choice<SerialHandshake>() ?? s.Handshake },
        { nameof(DtrEnable), (v, s) => s.DtrEnable = v.Boolean() ?? s.DtrEnable },
        { nameof(RtsEnable), (v, s) => s.RtsEnable = v.Boolean() ?? s.RtsEnable },
    };

    /// <summary>The local port: <c>COM3</c>, <c>/dev/ttyUSB0</c>, or any device path or link to one.</summary>
    public string? PortName { get; set; }

    /// <summary>Line speed in bits per second, one of the standard rates 300-230400. Default 9600.</summary>
    public int? BaudRate { get; set; }

    /// <summary>Data bits per character, 7 or 8. Default 7.</summary>
    public int? DataBits { get; set; }

    /// <summary>Parity bit: None, Even or Odd. Default Even.</summary>
    public SerialParity? Parity { get; set; }

    /// <summary>Stop bits: One or Two (also written 1 or 2). Default Two.</summary>
    public SerialStopBits? StopBits { get; set; }

    /// <summary>Flow control of a local port: None, RequestToSend or XOnXOff. Default None.</summary>
    public SerialHandshake? Handshake { get; set; }

    /// <summary>Raise DTR on a local port once it is open. Default false.</summary>
    public bool? DtrEnable { get; set; }

    /// <summary>Raise RTS on a local port once it is open (not with RequestToSend handshake). Default false.</summary>
    public bool? RtsEnable { get; set; }

    internal override string Key => "Serial";

    internal override string ChoiceKey => "Serial:PortName";

    internal override string What => "a local serial port";

    internal override string Hint => "Serial:PortName (a serial port such as COM3 or /dev/ttyUSB0)";

    internal override IEnumerable<string> KeyNames => Keys;

    internal override bool IsChosen => PortName is not null;

    /// <summary>The line settings the transport takes; unset values are Omron's defaults.</summary>
    internal SerialLineSettings ToLineSettings()
    {
        var line = new SerialLineSettings();
        line.PortName = PortName ?? line.PortName;
        line.BaudRate = BaudRate ?? line.BaudRate;
        line.DataBits = DataBits ?? line.DataBits;
        line.Parity = Parity ?? line.Parity;
        line.StopBits = StopBits ?? line.StopBits;
        line.Handshake = Handshake ?? line.Handshake;
        line.DtrEnable = DtrEnable ?? line.DtrEnable;
        line.RtsEnable = RtsEnable ?? line.RtsEnable;
        return line;
    }

    internal override void Read(SettingValue value) => value.Section(Keys, this);

    internal override void Check(HostLinkClientSettings client, List<HostLinkSettingsProblem> problems)
    {
        void Add(string key, string? problem)
        {
            if (problem is not null)
            {
                problems.Add(new HostLinkSettingsProblem("Serial:" + key, problem));
            }
        }

        Add(nameof(PortName), PortName is null ? null : SettingRules.PortName(PortName));
        Add(nameof(BaudRate), BaudRate is { } baud ? SettingRules.BaudRate(baud) : null);
        Add(nameof(DataBits), DataBits is { } bits ? SettingRules.DataBits(bits) : null);
        Add(nameof(Parity), Parity is { } parity ? SettingRules.Defined(parity) : null);
        Add(nameof(StopBits), StopBits is { } stop ? SettingRules.Defined(stop) : null);
        Add(nameof(Handshake), Handshake is { } handshake ? SettingRules.Defined(handshake) : null);
        Add(nameof(RtsEnable), SettingRules.RtsEnable(RtsEnable == true, Handshake == SerialHandshake.RequestToSend));
        if (!IsChosen && client.Endpoints.Any(e => e.IsChosen))
        {
            // Behind a serial-device server only the line's speed and format matter here; the rest is the server's.
            const string why = "applies to a local serial port; the serial-device server's own settings control it";
            Add(nameof(Handshake), Handshake is null ? null : why);
            Add(nameof(DtrEnable), DtrEnable is null ? null : why);
            Add(nameof(RtsEnable), RtsEnable is null ? null : why);
        }
    }

    internal override IHostLinkTransport CreateTransport(HostLinkClientSettings client) => new SerialTransport(ToLineSettings());
}
