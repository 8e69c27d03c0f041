using System.Net;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// The <c>Status</c> section: a read-only status page served by the gateway (lines, units, tags live, the line trace,
/// the outputs). Opt-in: without the section, or with <c>Enabled: false</c>, nothing listens.
/// </summary>
internal sealed class StatusOptions
{
    /// <summary>The configuration section these options bind to.</summary>
    public const string SectionName = "Status";

    /// <summary>The address listened on unless one is set: this machine only.</summary>
    public const string DefaultAddress = "127.0.0.1";

    /// <summary>The port listened on unless one is set.</summary>
    public const int DefaultPort = 9680;

    /// <summary>The fewest characters an access token may have.</summary>
    public const int ShortestToken = 16;

    /// <summary>False to keep the section in the file without serving the page. Default true.</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>
    /// The IP address the page listens on: <c>127.0.0.1</c> (default, this machine only), <c>::1</c>, an address of
    /// this machine, or <c>0.0.0.0</c>/<c>::</c> for every interface. Any address but a loopback one needs
    /// <see cref="AccessToken"/>.
    /// </summary>
    public string Address { get; set; } = DefaultAddress;

    /// <summary>The TCP port. Default 9680.</summary>
    public int Port { get; set; } = DefaultPort;

    /// <summary>
    /// The token every request must carry (<c>Authorization: Bearer …</c>, or once as <c>?token=…</c>, which a
    /// browser then keeps as a cookie); required for a non-loopback <see cref="Address"/>, optional on loopback.
    /// Set it in the environment (<c>Status__AccessToken</c>), not in the file.
    /// </summary>
    public string? AccessToken { get; set; }

    /// <summary>How many frames the line trace keeps per link (the last ones). Default 500.</summary>
    public int TraceFrames { get; set; } = 500;

    /// <summary>How often an open page is sent what changed. Default 500 ms.</summary>
    public TimeSpan RefreshInterval { get; set; } = TimeSpan.FromMilliseconds(500);

    /// <summary>The address as an <see cref="IPAddress"/>; null when it is none.</summary>
    public IPAddress? IPAddress => IPAddress.TryParse(Address?.Trim(), out IPAddress? address) ? address : null;

    /// <summary>Whether a token is set.</summary>
    public bool HasToken => !string.IsNullOrEmpty(AccessToken);
}
