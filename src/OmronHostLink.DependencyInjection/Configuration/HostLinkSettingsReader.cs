using System.Globalization;
using Microsoft.Extensions.Configuration;
using OmronHostLink.Transports;

namespace OmronHostLink.DependencyInjection.Configuration;

/// <summary>
/// Reads a client's configuration section into <see cref="HostLinkClientSettings"/>, key by key, and records every
/// key it cannot use (unknown, misspelt, unconvertible, a value where a section belongs) instead of stopping at the
/// first or passing over it. Keys are matched without regard to case, as configuration does.
/// </summary>
/// <remarks>
/// The configuration binder is not used: it stops at the first value it cannot convert, its messages name .NET types,
/// its enum conversion takes any integer, and its TimeSpan conversion has no unit forms such as <c>300ms</c>.
/// </remarks>
internal static class HostLinkSettingsReader
{
    private static readonly KeyTable<HostLinkSerialSettings> SerialKeys = new("a serial line setting")
    {
        { "PortName", (v, s) => s.PortName = v.Text() ?? s.PortName },
        { "BaudRate", (v, s) => s.BaudRate = v.Integer() ?? s.BaudRate },
        { "DataBits", (v, s) => s.DataBits = v.Integer() ?? s.DataBits },
        { "Parity", (v, s) => s.Parity = v.Choice<SerialParity>() ?? s.Parity },
        { "StopBits", (v, s) => s.StopBits = v.Choice(("1", SerialStopBits.One), ("2", SerialStopBits.Two)) ?? s.StopBits },
        { "Handshake", (v, s) => s.Handshake = v.Choice<SerialHandshake>() ?? s.Handshake },
        { "DtrEnable", (v, s) => s.DtrEnable = v.Boolean() ?? s.DtrEnable },
        { "RtsEnable", (v, s) => s.RtsEnable = v.Boolean() ?? s.RtsEnable },
    };

    private static readonly KeyTable<HostLinkTcpSettings> TcpKeys = new("a TCP setting")
    {
        { "Host", (v, t) => t.Host = v.Text() ?? t.Host },
        { "Port", (v, t) => t.Port = v.Integer() ?? t.Port },
        { "ConnectTimeout", (v, t) => t.ConnectTimeout = v.Duration() ?? t.ConnectTimeout },
    };

    private static readonly KeyTable<HostLinkClientSettings> ClientKeys = new("a Host Link client setting")
    {
        { "Serial", (v, s) => v.Section(SerialKeys, s.Serial) },
        { "Tcp", (v, s) => ReadTcp(v, s.Tcp) },
        { "UnitNumber", (v, s) => s.UnitNumber = v.Integer() ?? s.UnitNumber },
        { "Protocol", (v, s) => s.Protocol = v.Choice<HostLinkCommandSet>() ?? s.Protocol },
        { "TurnaroundAllowance", (v, s) => s.TurnaroundAllowance = v.Duration() ?? s.TurnaroundAllowance },
        { "ReadRetries", (v, s) => s.ReadRetries = v.Integer() ?? s.ReadRetries },
        { "WriteRetries", (v, s) => s.WriteRetries = v.Integer() ?? s.WriteRetries },
        { "WordOrder", (v, s) => s.WordOrder = v.Choice<WordOrder>() ?? s.WordOrder },
        { "LocalEcho", (v, s) => s.LocalEcho = v.Boolean() ?? s.LocalEcho },
        { "FinsResponseWait", (v, s) => s.FinsResponseWait = v.Integer() ?? s.FinsResponseWait },
        { "AllowReadModifyWriteBits", (v, s) => s.AllowReadModifyWriteBits = v.Boolean() ?? s.AllowReadModifyWriteBits },
        { "Model", (v, s) => s.Model = v.Text() ?? s.Model },
    };

    // Names people reach for that live elsewhere here (including the worker sample's earlier ones).
    private static readonly Dictionary<string, string> Hints = new(StringComparer.OrdinalIgnoreCase)
    {
        ["Unit"] = "UnitNumber",
        ["LineBaudRate"] = "Serial:BaudRate",
        ["Baud"] = "Serial:BaudRate",
        ["Port"] = "Serial:PortName or Tcp:Port",
    };

    /// <summary>Reads <paramref name="configuration"/> into <paramref name="settings"/>, recording problems in it.</summary>
    public static void Read(IConfiguration configuration, HostLinkClientSettings settings)
    {
        if (configuration is IConfigurationSection section && !section.Exists())
        {
            settings.ReadProblems.Add(new SettingsProblem(
                "", "the section is missing or empty; check the client's name and write Serial:PortName or Tcp in it"));
            return;
        }

        ClientKeys.Read(configuration, "", settings, settings.ReadProblems);
    }

    private static void ReadTcp(ConfigurationValue value, HostLinkTcpSettings tcp)
    {
        if (value.IsSection)
        {
            value.Section(TcpKeys, tcp);
            return;
        }

        string? text = value.Text();
        if (text is null)
        {
            return;
        }

        int colon = text.LastIndexOf(':');
        string host = colon > 0 ? text.Substring(0, colon).Trim() : "";
        string port = colon > 0 ? text.Substring(colon + 1).Trim() : "";
        if (host.StartsWith("[", StringComparison.Ordinal) && host.EndsWith("]", StringComparison.Ordinal))
        {
            host = host.Substring(1, host.Length - 2);
        }
        else if (host.IndexOf(':') >= 0)
        {
            value.Problem($"'{text}': write an IPv6 address in brackets, e.g. [fd00::5]:4001");
            return;
        }

        if (host.Length == 0 || port.Length == 0)
        {
            value.Problem($"'{text}' is not host:port (e.g. 192.0.2.10:4001), or write a section with Host and Port");
            return;
        }

        if (!int.TryParse(port, NumberStyles.None, CultureInfo.InvariantCulture, out int number) || number is < 1 or > 65535)
        {
            value.Problem($"'{text}': the port '{port}' is not a number 1-65535");
            return;
        }

        tcp.Host = host;
        tcp.Port = number;
    }

    /// <summary>The keys one section may hold, and how each is read.</summary>
    private sealed class KeyTable<T> : IEnumerable<string>
    {
        private readonly Dictionary<string, Action<ConfigurationValue, T>> _readers = new(StringComparer.OrdinalIgnoreCase);
        private readonly List<string> _names = new();
        private readonly string _what;

        public KeyTable(string what) => _what = what;

        public void Add(string name, Action<ConfigurationValue, T> read)
        {
            _readers.Add(name, read);
            _names.Add(name);
        }

        public void Read(IConfiguration configuration, string prefix, T target, List<SettingsProblem> problems)
        {
            foreach (IConfigurationSection child in configuration.GetChildren())
            {
                string key = prefix + child.Key;
                if (_readers.TryGetValue(child.Key, out Action<ConfigurationValue, T>? read))
                {
                    read(new ConfigurationValue(child, prefix + Canonical(child.Key), problems), target);
                }
                else
                {
                    problems.Add(new SettingsProblem(key, Unknown(child.Key, prefix)));
                }
            }
        }

        public IEnumerator<string> GetEnumerator() => _names.GetEnumerator();

        System.Collections.IEnumerator System.Collections.IEnumerable.GetEnumerator() => GetEnumerator();

        private string Canonical(string key) => _names.First(n => n.Equals(key, StringComparison.OrdinalIgnoreCase));

        private string Unknown(string key, string prefix)
        {
            string? suggestion = null;
            if (prefix.Length == 0)
            {
                if (Hints.TryGetValue(key, out string? hint))
                {
                    suggestion = hint;
                }
                else if (SerialKeys.Any(n => n.Equals(key, StringComparison.OrdinalIgnoreCase)))
                {
                    suggestion = "Serial:" + SerialKeys.First(n => n.Equals(key, StringComparison.OrdinalIgnoreCase));
                }
                else if (TcpKeys.Any(n => n.Equals(key, StringComparison.OrdinalIgnoreCase)))
                {
                    suggestion = "Tcp:" + TcpKeys.First(n => n.Equals(key, StringComparison.OrdinalIgnoreCase));
                }
            }

            suggestion ??= _names
                .Select(n => (Name: n, Distance: EditDistance(key.ToUpperInvariant(), n.ToUpperInvariant())))
                .Where(c => c.Distance <= Math.Max(1, c.Name.Length / 4))
                .OrderBy(c => c.Distance)
                .Select(c => prefix + c.Name)
                .FirstOrDefault();
            return suggestion is null
                ? $"not {_what} (known: {string.Join(", ", _names)})"
                : $"not {_what}; did you mean {suggestion}?";
        }

        private static int EditDistance(string a, string b)
        {
            int[] previous = Enumerable.Range(0, b.Length + 1).ToArray();
            int[] current = new int[b.Length + 1];
            for (int i = 1; i <= a.Length; i++)
            {
                current[0] = i;
                for (int j = 1; j <= b.Length; j++)
                {
                    int substitute = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
                    current[j] = Math.Min(substitute, Math.Min(previous[j], current[j - 1]) + 1);
                }

                (previous, current) = (current, previous);
            }

            return previous[b.Length];
        }
    }

    /// <summary>One configuration key's value, converted on request; a value that cannot be converted is recorded.</summary>
    private sealed class ConfigurationValue
    {
        private readonly IConfigurationSection _section;
        private readonly string _key;
        private readonly List<SettingsProblem> _problems;

        public ConfigurationValue(IConfigurationSection section, string key, List<SettingsProblem> problems)
        {
            _section = section;
            _key = key;
            _problems = problems;
        }

        public bool IsSection => _section.GetChildren().Any();

        public void Problem(string message) => _problems.Add(new SettingsProblem(_key, message));

        /// <summary>The text; null when the key is null in the file (left at the default) or cannot be used.</summary>
        public string? Text()
        {
            if (IsSection)
            {
                Problem("expects a value, not a section");
                return null;
            }

            string? text = _section.Value;
            if (text is not null && text.Trim().Length == 0)
            {
                Problem("is empty; write a value, or remove the key to use the default");
                return null;
            }

            return text;
        }

        public int? Integer()
        {
            string? text = Text();
            if (text is null)
            {
                return null;
            }

            if (int.TryParse(text.Trim(), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int value))
            {
                return value;
            }

            Problem($"'{text}' is not a whole number");
            return null;
        }

        public bool? Boolean()
        {
            string? text = Text();
            if (text is null)
            {
                return null;
            }

            if (bool.TryParse(text.Trim(), out bool value))
            {
                return value;
            }

            Problem($"'{text}' is not true or false");
            return null;
        }

        public TimeSpan? Duration()
        {
            string? text = Text();
            if (text is null)
            {
                return null;
            }

            if (OmronHostLink.Duration.TryParse(text, out TimeSpan value, out string? error))
            {
                return value;
            }

            Problem(error!);
            return null;
        }

        /// <summary>An enum member by name (any case); numbers only where <paramref name="aliases"/> allow them.</summary>
        public TEnum? Choice<TEnum>(params (string Text, TEnum Value)[] aliases)
            where TEnum : struct, Enum
        {
            string? text = Text();
            if (text is null)
            {
                return null;
            }

            string t = text.Trim();
            foreach (string name in Enum.GetNames(typeof(TEnum)))
            {
                if (name.Equals(t, StringComparison.OrdinalIgnoreCase))
                {
                    return (TEnum)Enum.Parse(typeof(TEnum), name);
                }
            }

            foreach ((string alias, TEnum value) in aliases)
            {
                if (alias.Equals(t, StringComparison.OrdinalIgnoreCase))
                {
                    return value;
                }
            }

            IEnumerable<string> accepted = Enum.GetNames(typeof(TEnum)).Concat(aliases.Select(a => a.Text));
            Problem($"'{text}' is not one of {string.Join(", ", accepted)}");
            return null;
        }

        public void Section<T>(KeyTable<T> keys, T target)
        {
            if (!IsSection && _section.Value is not null)
            {
                Problem($"expects a section ({string.Join(", ", keys)}), not a value");
                return;
            }

            keys.Read(_section, _key + ":", target, _problems);
        }
    }
}
