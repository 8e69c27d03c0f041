using System.Net;
using System.Net.Sockets;
using System.Text.Json;
using OmronHostLink.Cli;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Cli.Tests;

/// <summary>What one run of the command line produced.</summary>
internal sealed record CliResult(int ExitCode, string Out, string Err)
{
    /// <summary>stdout as exactly one JSON document.</summary>
    public JsonElement Json()
    {
        string[] lines = Lines();
        lines.Should().HaveCount(1, "--json prints exactly one document; stdout was: {0}", Out);
        return JsonDocument.Parse(lines[0]).RootElement.Clone();
    }

    public string[] Lines() => Out.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);

    public override string ToString() => $"exit {ExitCode}\nstdout:\n{Out}\nstderr:\n{Err}";
}

/// <summary>Runs <c>hostlink</c> in process with captured output.</summary>
internal static class Cli
{
    public static Task<CliResult> RunAsync(params string[] args) => RunAsync(CancellationToken.None, args);

    public static async Task<CliResult> RunAsync(CancellationToken cancellationToken, params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int exit = await CliApp.RunAsync(WithAllowance(args), TextWriter.Synchronized(stdout), TextWriter.Synchronized(stderr), cancellationToken);
        return new CliResult(exit, stdout.ToString(), stderr.ToString());
    }

    /// <summary>Runs the command line with serial ports opened by <paramref name="serialPorts"/> (an emulated line), the arguments as given.</summary>
    public static async Task<CliResult> RunAsync(Func<Transports.SerialLineSettings, Transports.IHostLinkTransport> serialPorts, params string[] args)
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        int exit = await CliApp.RunAsync(args, TextWriter.Synchronized(stdout), TextWriter.Synchronized(stderr), serialPorts, CancellationToken.None);
        return new CliResult(exit, stdout.ToString(), stderr.ToString());
    }

    /// <summary>
    /// The command line, with the lossless line's allowance (<see cref="Allowances.LosslessLine"/>) as <c>--timeout</c>
    /// where a command talks to a PLC (<c>--tcp</c> or <c>--port</c>) and the test sets no <c>--timeout</c>: the PLCs
    /// these tests talk to answer every frame, so a deadline must not fail a test because the machine is busy. A scan
    /// keeps its own short default, since finding the units that do not answer is its job, and so does <c>detect</c>;
    /// <c>simulate</c> and <c>monitor-line</c> take no allowance.
    /// </summary>
    public static string[] WithAllowance(string[] args)
        => (args.Contains("--tcp") || args.Contains("--port")) && !args.Contains("--timeout") && args.FirstOrDefault() is not ("scan" or "simulate" or "monitor-line" or "detect")
            ? [.. args, "--timeout", Allowances.LosslessLineText]
            : args;

    /// <summary>
    /// The probe wait of a scan that must find the units that are there: a scan tells an absent unit by this deadline,
    /// so each absent one costs it, and a present one must answer within it even on a busy machine.
    /// </summary>
    public const string ScanTimeout = "2s";

    /// <summary>A loopback port nobody listens on.</summary>
    public static int ClosedPort()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        listener.Stop();
        return port;
    }
}

/// <summary>A virtual PLC served on a loopback TCP port in this process, for the CLI to talk to.</summary>
internal sealed class SimulatedPlc : IAsyncDisposable
{
    private SimulatedPlc(VirtualPlc plc, TcpSimulatorHost host)
    {
        Plc = plc;
        Host = host;
    }

    public VirtualPlc Plc { get; }

    public TcpSimulatorHost Host { get; }

    public string Endpoint => $"127.0.0.1:{Host.EndPoint.Port}";

    public static async Task<SimulatedPlc> StartAsync(PlcMode mode = PlcMode.Program, IReadOnlyList<int>? units = null, TimeSpan turnaround = default)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { InitialMode = mode, Units = units ?? [0], Turnaround = turnaround });
        var host = new TcpSimulatorHost(plc);
        await host.StartAsync();
        return new SimulatedPlc(plc, host);
    }

    /// <summary>The command line with <c>--tcp</c> pointing here appended.</summary>
    public Task<CliResult> RunAsync(params string[] args) => Cli.RunAsync([.. args, "--tcp", Endpoint]);

    public ValueTask DisposeAsync() => Host.DisposeAsync();
}
