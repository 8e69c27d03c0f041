using System.CommandLine;
using System.IO.Ports;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>ports</c>: lists the serial ports of this machine.</summary>
internal static class PortsCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("ports", "List serial ports (ptys and socat links are not listed; pass their path to --port).");
        Option<bool> json = CliContext.JsonOption();
        command.Add(json);
        context.SetAction(command, json, (_, output, _) =>
        {
            string[] ports = SerialPort.GetPortNames();
            Array.Sort(ports, StringComparer.Ordinal);
            output.Result(
                w =>
                {
                    if (ports.Length == 0)
                    {
                        w.WriteLine("No serial ports found. Ptys and socat links are never listed: pass their path to --port.");
                    }

                    foreach (string port in ports)
                    {
                        w.WriteLine(port);
                    }
                },
                j =>
                {
                    j.WriteStartObject();
                    j.WriteStartArray("ports");
                    foreach (string port in ports)
                    {
                        j.WriteStringValue(port);
                    }

                    j.WriteEndArray();
                    j.WriteEndObject();
                });
            return Task.FromResult(ExitCodes.Success);
        });
        return command;
    }
}
