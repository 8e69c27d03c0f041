using LineSetting = OmronHostLink.Declare<OmronHostLink.HostLinkSerialSettings, OmronHostLink.Transports.SerialLineSettings>;
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
    /// <summary>The BaudRate setting.</summary>
    internal static readonly Setting<HostLinkSerialSettings, SerialLineSettings, int?> BaudRateSetting =
        LineSetting.Value(nameof(BaudRate), s => s.BaudRate, (s, v) => s.BaudRate = v, v => v.Integer(), SettingRules.BaudRate, o => o.BaudRate, (o, v) => o.BaudRate = v);

    /// <summary>The DataBits setting.</summary>
    internal static readonly Setting<HostLinkSerialSettings, SerialLineSettings, int?> DataBitsSetting =
        LineSetting.Value(nameof(DataBits), s => s.DataBits, (s, v) => s.DataBits = v, v => v.Integer(), SettingRules.DataBits, o => o.DataBits, (o, v) => o.DataBits = v);

    /// <summary>The Parity setting.</summary>
    internal static readonly Setting<HostLinkSerialSettings, SerialLineSettings, SerialParity?> ParitySetting =
        LineSetting.Value(nameof(Parity), s => s.Parity, (s, v) => s.Parity = v, v => v.Choice<SerialParity>(), SettingRules.Defined, o => o.Parity, (o, v) => o.Parity = v);

    /// <summary>The StopBits setting.</summary>
    internal static readonly Setting<HostLinkSerialSettings, SerialLineSettings, SerialStopBits?> StopBitsSetting =
        LineSetting.Value(nameof(StopBits), s => s.StopBits, (s, v) => s.StopBits = v, v => v.Choice(("1", SerialStopBits.One), ("2", SerialStopBits.Two)), SettingRules.Defined, o => o.StopBits, (o, v) => o.StopBits = v);

    /// <summary>
    /// The serial line's settings, each declared once: key, reader, rule and how it applies to
    /// <see cref="SerialLineSettings"/> (whose new instance holds the default, Omron's 9600 7E2).
    /// </summary>
    internal static readonly Setting<HostLinkSerialSettings, SerialLineSettings>[] Declared =
    [
        LineSetting.Reference(nameof(PortName), s => s.PortName, (s, v) => s.PortName = v, v => v.Text(), SettingRules.PortName, o => o.PortName, (o, v) => o.PortName = v),
        BaudRateSetting,
        DataBitsSetting,
        ParitySetting,
        StopBitsSetting,
        LineSetting.Value(nameof(Handshake), s => s.Handshake, (s, v) => s.Handshake = v, v => v.Choice<SerialHandshake>(), SettingRules.Defined, o => o.Handshake, (o, v) => o.Handshake = v),
        LineSetting.Value(nameof(DtrEnable), s => s.DtrEnable, (s, v) => s.DtrEnable = v, v => v.Boolean(), null, o => o.DtrEnable, (o, v) => o.DtrEnable = v),
        LineSetting.Value(nameof(RtsEnable), s => s.RtsEnable, (s, v) => s.RtsEnable = v, v => v.Boolean(), null, o => o.RtsEnable, (o, v) => o.RtsEnable = v),
    ];

    private static readonly SettingKeys<HostLinkSerialSettings> Keys = SettingKeys<HostLinkSerialSettings>.Of("a serial line setting", Declared);

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
        foreach (Setting<HostLinkSerialSettings, SerialLineSettings> setting in Declared)
        {
            setting.Apply(this, line);
        }

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

        foreach (Setting<HostLinkSerialSettings, SerialLineSettings> setting in Declared)
        {
            Add(setting.Key, setting.Check(this));
        }

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
