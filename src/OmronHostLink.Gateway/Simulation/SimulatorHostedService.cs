using System.Net;
using System.Net.Sockets;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Gateway.Simulation;

/// <summary>
/// Runs a <see cref="VirtualPlc"/> on 127.0.0.1 inside the worker when <c>Simulator:Enabled</c> is true. Registered
/// before the polling service, so it listens before the first link connects, and stops after the links.
/// </summary>
internal sealed class SimulatorHostedService : IHostedService, IAsyncDisposable
{
    private readonly IOptions<SimulatorOptions> _options;
    private readonly ILogger _logger;
    private readonly IHostApplicationLifetime _lifetime;
    private TcpSimulatorHost? _host;
    private CancellationTokenSource? _animation;
    private Task? _animating;

    /// <summary>Creates the service.</summary>
    public SimulatorHostedService(IOptions<SimulatorOptions> options, ILogger<SimulatorHostedService> logger, IHostApplicationLifetime lifetime)
    {
        _options = options;
        _logger = logger;
        _lifetime = lifetime;
    }

    /// <summary>The virtual PLC, once started.</summary>
    public VirtualPlc? Plc { get; private set; }

    /// <inheritdoc/>
    public async Task StartAsync(CancellationToken cancellationToken)
    {
        SimulatorOptions o = _options.Value;
        if (!o.Enabled)
        {
            return;
        }

        var plc = new VirtualPlc(new VirtualPlcOptions
        {
            Units = o.UnitsOrDefault,
            Turnaround = o.Turnaround,
            BaudRate = o.BaudRate,
            Faults = o.Faults ?? new(),
        });
        foreach ((string address, string text) in o.Memory)
        {
            PlcAddress a = PlcAddress.Parse(address);
            MemoryValue.TryParse(a, text, out MemoryValue value, out _);
            if (value.Bit is { } bit)
            {
                plc.SetBit(address, bit);
            }
            else
            {
                plc.WriteWords(address, value.Words);
            }
        }

        var host = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, o.Port));
        try
        {
            await host.StartAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (SocketException e) when (e.SocketErrorCode == SocketError.AddressAlreadyInUse)
        {
            // One line, not the host's failure with two stack traces: another program (often a second gateway) has it.
            await host.DisposeAsync().ConfigureAwait(false);
            SimulatorLog.PortInUse(_logger, o.Port);
            Environment.ExitCode = ExitCodes.InvalidConfiguration;
            _lifetime.StopApplication();
            return;
        }

        _host = host;
        Plc = plc;
        string faults = plc.Options.Faults.Any ? $" with faults (seed {plc.Options.Faults.Seed})" : "";
        SimulatorLog.Started(_logger, string.Join(", ", o.UnitsOrDefault), host.EndPoint.ToString(), faults);
        if (o.Animate is { Address.Length: > 0 } animate)
        {
            _animation = new CancellationTokenSource();
            _animating = AnimateAsync(plc, animate, _animation.Token);
        }
    }

    /// <inheritdoc/>
    public async Task StopAsync(CancellationToken cancellationToken)
    {
        if (_animation is not null)
        {
            await _animation.CancelAsync().ConfigureAwait(false);
            await _animating!.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
            _animation.Dispose();
            _animation = null;
        }

        if (_host is not null)
        {
            await _host.StopAsync(cancellationToken).ConfigureAwait(false);
            _host = null;
            SimulatorLog.Stopped(_logger, Plc!.FaultCounters.ToString());
        }
    }

    /// <inheritdoc/>
    public async ValueTask DisposeAsync()
    {
        await StopAsync(CancellationToken.None).ConfigureAwait(false);
    }

    private static async Task AnimateAsync(VirtualPlc plc, AnimateOptions animate, CancellationToken cancellationToken)
    {
        using var timer = new PeriodicTimer(animate.Interval);
        while (await timer.WaitForNextTickAsync(cancellationToken).ConfigureAwait(false))
        {
            ushort value = plc.ReadWords(animate.Address, 1)[0];
            plc.WriteWords(animate.Address, [unchecked((ushort)(value + 1))]);
        }
    }
}
