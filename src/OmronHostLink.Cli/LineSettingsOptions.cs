using System.CommandLine;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli;

/// <summary>
/// <c>--baud</c>, <c>--data-bits</c>, <c>--parity</c> and <c>--stop-bits</c> of a command that opens serial ports itself
/// (<c>detect</c>, <c>monitor-line</c>) rather than through a client: each left out takes Omron's default (9600 7E2).
/// </summary>
internal sealed class LineSettingsOptions
{
    private static readonly SerialLineSettings Defaults = new();

    /// <param name="which">What the settings are, for the help: "the line's", "the settings tried first".</param>
    public LineSettingsOptions(string which)
    {
        Baud = OptionValues.OptionalInteger("--baud", $"Speed of {which} (default {Defaults.BaudRate}).", int.MinValue, int.MaxValue, "n");
        DataBits = OptionValues.OptionalInteger("--data-bits", $"Data bits of {which} (default {Defaults.DataBits}).", int.MinValue, int.MaxValue, $"{SettingRules.MinDataBits}|{SettingRules.MaxDataBits}");
        Parity = OptionValues.OptionalChoice("--parity", $"Parity of {which} (default {Defaults.Parity.ToString().ToLowerInvariant()}).", "none|even|odd", "none", "even", "odd");
        StopBits = OptionValues.OptionalInteger("--stop-bits", $"Stop bits of {which} (default {(int)Defaults.StopBits}).", int.MinValue, int.MaxValue, "1|2");
    }

    public Option<int?> Baud { get; }

    public Option<int?> DataBits { get; }

    public Option<string?> Parity { get; }

    public Option<int?> StopBits { get; }

    public void AddTo(Command command)
    {
        command.Add(Baud);
        command.Add(DataBits);
        command.Add(Parity);
        command.Add(StopBits);
    }

    /// <summary>The settings of port <paramref name="portName"/>, checked.</summary>
    /// <exception cref="UsageException">A setting is out of range; the message names the option.</exception>
    public SerialLineSettings Settings(ParseResult parse, string portName)
    {
        var settings = new SerialLineSettings
        {
            PortName = portName,
            BaudRate = parse.GetValue(Baud) ?? Defaults.BaudRate,
            DataBits = parse.GetValue(DataBits) ?? Defaults.DataBits,
            Parity = parse.GetValue(Parity) switch { "none" => SerialParity.None, "odd" => SerialParity.Odd, "even" => SerialParity.Even, _ => Defaults.Parity },
            StopBits = parse.GetValue(StopBits) is { } stop ? (SerialStopBits)stop : Defaults.StopBits,
        };
        try
        {
            settings.Validate();
        }
        catch (ArgumentException e)
        {
            throw new UsageException(OptionValues.SerialMessage(e), e);
        }

        return settings;
    }
}
