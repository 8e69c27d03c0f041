using OmronHostLink.DependencyInjection.Configuration;

namespace OmronHostLink.DependencyInjection;

/// <summary>
/// One Host Link client as configuration describes it: the link (a local serial port or a TCP serial-device server)
/// and how the client talks over it. Every setting left unset (null) takes the library's default.
/// </summary>
/// <remarks>
/// Bound from a configuration section by
/// <see cref="Microsoft.Extensions.DependencyInjection.HostLinkServiceCollectionExtensions.AddHostLinkClient(Microsoft.Extensions.DependencyInjection.IServiceCollection, string, Microsoft.Extensions.Configuration.IConfiguration, Action{HostLinkClientSettings}?)"/>
/// or set in code, and checked when the host starts. Set exactly one of <see cref="HostLinkSerialSettings.PortName"/>
/// (in <see cref="Serial"/>) and <see cref="HostLinkTcpSettings.Host"/> (in <see cref="Tcp"/>).
/// </remarks>
public sealed class HostLinkClientSettings
{
    /// <summary>
    /// The serial line: for a local port, the port and its settings; behind a serial-device server, the line's speed
    /// and character format, from which frame deadlines are derived.
    /// </summary>
    public HostLinkSerialSettings Serial { get; set; } = new();

    /// <summary>A serial-device server (or the simulator) reached over TCP instead of a local port.</summary>
    public HostLinkTcpSettings Tcp { get; set; } = new();

    /// <summary>The unit number the client addresses, 0-31. Default 0.</summary>
    public int? UnitNumber { get; set; }

    /// <summary>The command set reads and writes use: <see cref="HostLinkCommandSet.CMode"/> (default) or <see cref="HostLinkCommandSet.Fins"/>.</summary>
    public HostLinkCommandSet? Protocol { get; set; }

    /// <summary>
    /// How long the PLC (and a gateway between) may take to start answering a frame, on top of the frame's wire time.
    /// More than zero, at most 1 minute. Default 300 ms.
    /// </summary>
    public TimeSpan? TurnaroundAllowance { get; set; }

    /// <summary>How many times a read is repeated after a timeout or a damaged frame, 0-10. Default 2.</summary>
    public int? ReadRetries { get; set; }

    /// <summary>
    /// How many times a write is repeated after a timeout or a damaged frame, 0-10. Default 0: a write whose answer was
    /// lost may have been carried out.
    /// </summary>
    public int? WriteRetries { get; set; }

    /// <summary>How 32-bit values lie in two words. Default <see cref="OmronHostLink.WordOrder.LowWordFirst"/> (Omron's layout).</summary>
    public WordOrder? WordOrder { get; set; }

    /// <summary>The line echoes what we send (2-wire RS-485 without echo suppression). Default false.</summary>
    public bool? LocalEcho { get; set; }

    /// <summary>The FINS response wait time sent in every FINS frame, 0-15 in units of 10 ms. Default 0.</summary>
    public int? FinsResponseWait { get; set; }

    /// <summary>
    /// Allow bit writes by reading the word, changing the bit and writing the word back. Default false: a change the PLC
    /// program makes to the word between the read and the write is lost.
    /// </summary>
    public bool? AllowReadModifyWriteBits { get; set; }

    /// <summary>
    /// The PLC model addresses and commands are checked against before anything is sent (see
    /// <see cref="HostLinkClientOptions.Model"/>): CPM1A, CP1E-E, C200HS, CS1, ..., or auto to ask the PLC (MM).
    /// Default none: the CS/CJ sizes only.
    /// </summary>
    public string? Model { get; set; }

    /// <summary>The configuration path the settings were read from (empty for a configuration root); null when set in code only.</summary>
    internal string? ConfigurationPath { get; set; }

    /// <summary>Values configuration held that could not be read; reported with the other problems at start.</summary>
    internal List<SettingsProblem> ReadProblems { get; } = new();
}
