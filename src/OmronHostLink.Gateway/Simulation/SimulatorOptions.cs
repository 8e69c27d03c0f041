using System.Globalization;
using OmronHostLink.Simulator.Faults;

namespace OmronHostLink.Gateway.Simulation;

/// <summary>The <c>Simulator</c> section: an in-process virtual PLC on 127.0.0.1 for trying the worker without a PLC.</summary>
internal sealed class SimulatorOptions
{
    /// <summary>The configuration section these options bind to.</summary>
    public const string SectionName = "Simulator";

    /// <summary>Start the simulator. Default false (appsettings.Development.json turns it on).</summary>
    public bool Enabled { get; set; }

    /// <summary>The TCP port on 127.0.0.1. Default 9601.</summary>
    public int Port { get; set; } = 9601;

    /// <summary>The unit numbers the virtual PLC answers. Default [0].</summary>
    public int[]? Units { get; set; }

    /// <summary>
    /// Initial memory: address → value. Words as <c>"120, 340"</c> (decimal, -32768..65535, or <c>0x1234</c>),
    /// a bit as <c>"true"</c>/<c>"false"</c> (<c>"CIO10.03": "true"</c>), text as <c>"'PUMP 1'"</c> (single quotes).
    /// </summary>
    public Dictionary<string, string> Memory { get; set; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>Words incremented on a timer, so that OnChange groups have something to report.</summary>
    public AnimateOptions? Animate { get; set; }

    /// <summary>The PLC's answer delay. Default 0.</summary>
    public TimeSpan Turnaround { get; set; }

    /// <summary>Emulated line speed (0 = as fast as TCP goes). Default 0.</summary>
    public int BaudRate { get; set; }

    /// <summary>Fault injection (Seed, Drop, Corrupt, Noise, Truncate, Late, LateBy, Echo); default none.</summary>
    public FaultOptions Faults { get; set; } = new();

    /// <summary>The unit numbers, defaulted.</summary>
    public IReadOnlyList<int> UnitsOrDefault => Units is { Length: > 0 } u ? u : [0];
}

/// <summary>A word the simulator increments every <see cref="Interval"/>.</summary>
internal sealed class AnimateOptions
{
    /// <summary>The word address. Empty for none.</summary>
    public string Address { get; set; } = "";

    /// <summary>Time between increments. Default 1 s.</summary>
    public TimeSpan Interval { get; set; } = TimeSpan.FromSeconds(1);
}

/// <summary>A parsed <see cref="SimulatorOptions.Memory"/> value.</summary>
internal readonly record struct MemoryValue(ushort[]? Words, bool? Bit)
{
    /// <summary>Parses a memory value for <paramref name="address"/>.</summary>
    public static bool TryParse(PlcAddress address, string? text, out MemoryValue value, out string error)
    {
        value = default;
        error = "";
        text = text?.Trim() ?? "";
        if (address.IsBit)
        {
            bool? bit = text.ToLowerInvariant() switch
            {
                "true" or "1" => true,
                "false" or "0" => false,
                _ => null,
            };
            if (bit is { } b)
            {
                value = new MemoryValue(null, b);
                return true;
            }

            error = $"'{text}' is not a bit value (true, false, 1 or 0).";
            return false;
        }

        if (text.Length >= 2 && text[0] == '\'' && text[^1] == '\'')
        {
            string s = text.Substring(1, text.Length - 2);
            try
            {
                value = new MemoryValue(PlcWords.FromString(s), null);
                return true;
            }
            catch (ArgumentException e)
            {
                error = e.Message;
                return false;
            }
        }

        string[] parts = text.Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
        if (parts.Length == 0)
        {
            error = "no value is given.";
            return false;
        }

        var words = new ushort[parts.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            string p = parts[i];
            if (p.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
                && ushort.TryParse(p.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out ushort hex))
            {
                words[i] = hex;
            }
            else if (int.TryParse(p, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int n) && n is >= short.MinValue and <= ushort.MaxValue)
            {
                words[i] = unchecked((ushort)n);
            }
            else
            {
                error = $"'{p}' is not a word (-32768..65535 or 0x0000..0xFFFF).";
                return false;
            }
        }

        value = new MemoryValue(words, null);
        return true;
    }
}
