using System.Globalization;
using System.Net;
using System.Net.Sockets;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// Whether a configured host can be one, checked on its text before anything resolves it: an IPv4 address, an IPv6
/// address, or a DNS name (RFC 1123 labels). A URL (<c>tcp://…</c>) or a dotted number that is no IPv4 address
/// (<c>127.0.0.1.5</c>) would otherwise be looked up as a host name, and retried for ever.
/// </summary>
internal static class HostSyntax
{
    /// <summary>Why <paramref name="host"/> is not a host name or address; null when it is one.</summary>
    public static string? Problem(string host)
    {
        ArgumentNullException.ThrowIfNull(host);
        if (host.Length == 0)
        {
            return "it is empty";
        }

        if (host.Contains("://", StringComparison.Ordinal))
        {
            return "it is a URL; write the host alone (127.0.0.1, plc-gw-1.plant.local), without a scheme";
        }

        if (host.Contains(':', StringComparison.Ordinal))
        {
            return IPAddress.TryParse(host, out IPAddress? v6) && v6.AddressFamily == AddressFamily.InterNetworkV6
                ? null
                : "it holds ':' but is no IPv6 address";
        }

        string[] labels = host.Split('.');
        if (labels.All(l => l.Length > 0 && l.All(char.IsAsciiDigit)))
        {
            // All numeric: only a dotted-quad IPv4 address, each part 0-255, is one.
            return labels.Length == 4 && labels.All(l => int.Parse(l, NumberStyles.None, CultureInfo.InvariantCulture) <= 255 && (l.Length == 1 || l[0] != '0'))
                ? null
                : "it looks like an IPv4 address but is not one (four numbers 0-255, such as 192.168.1.20)";
        }

        if (host.Length > 253)
        {
            return "a host name has at most 253 characters";
        }

        foreach (string label in labels)
        {
            if (label.Length is 0 or > 63 || label[0] == '-' || label[^1] == '-' || !label.All(c => char.IsAsciiLetterOrDigit(c) || c == '-'))
            {
                return $"'{label}' is not a host name label (letters, digits and '-', 1-63 characters, not starting or ending with '-')";
            }
        }

        return labels[^1].All(char.IsAsciiDigit) ? "a host name's last label is not all digits" : null;
    }
}
