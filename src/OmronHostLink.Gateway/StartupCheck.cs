using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Simulation;

namespace OmronHostLink.Gateway;

/// <summary>
/// The start-time check of the sections the host needs before it is built — <c>HostLink</c> (its links' clients are
/// registered only when it passes) and <c>Simulator</c> — run once, ahead, on the same binding and with the same
/// validators the host runs at start; their verdicts are kept, so the start reports these and does not judge again.
/// </summary>
internal static class StartupCheck
{
    /// <summary>Whether both sections pass.</summary>
    public static bool Passes(GatewayConfiguration gateway)
    {
        var simulator = new SimulatorOptions();
        gateway.Bind(SimulatorOptions.SectionName, simulator);
        return new GatewayOptionsValidator(gateway).Validate(null, gateway.HostLink).Succeeded
            && new SimulatorOptionsValidator(gateway).Validate(null, simulator).Succeeded;
    }
}
