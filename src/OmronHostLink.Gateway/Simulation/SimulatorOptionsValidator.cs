using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Simulation;

/// <summary>Checks the <c>Simulator</c> section, and when the simulator is enabled its values, naming bad fields by path.</summary>
/// <param name="gateway">The configuration as the gateway reads it.</param>
internal sealed class SimulatorOptionsValidator(GatewayConfiguration gateway) : SectionValidator<SimulatorOptions>(gateway, SimulatorOptions.SectionName)
{
    /// <inheritdoc/>
    protected override bool IsOn(SimulatorOptions options) => options.Enabled;

    /// <inheritdoc/>
    protected override void Check(SimulatorOptions options, List<string> failures)
    {
        const string root = SimulatorOptions.SectionName;
        if (options.Port is < 1 or > 65535)
        {
            failures.Add($"{root}:Port must be 1-65535; it is {options.Port}.");
        }

        if (options.BaudRate is < 0 or > 1_000_000)
        {
            failures.Add($"{root}:BaudRate must be 0 (as fast as TCP goes) to 1000000; it is {options.BaudRate}.");
        }

        foreach (int unit in options.UnitsOrDefault)
        {
            if (HostLinkRules.CheckUnitNumber(unit) is { } unitProblem)
            {
                failures.Add($"{root}:Units: {unitProblem}.");
            }
        }

        foreach ((string address, string text) in options.Memory)
        {
            if (!PlcAddress.TryParse(address, out PlcAddress a))
            {
                failures.Add($"{root}:Memory:{address}: '{address}' is not a PLC address.");
            }
            else if (!MemoryValue.TryParse(a, text, out _, out string error))
            {
                failures.Add($"{root}:Memory:{address}: {error}");
            }
        }

        if (options.Animate is { Address.Length: > 0 } animate)
        {
            if (!PlcAddress.TryParse(animate.Address, out PlcAddress a) || a.IsBit)
            {
                failures.Add($"{root}:Animate:Address '{animate.Address}' is not a word address.");
            }

            if (animate.Interval <= TimeSpan.Zero)
            {
                failures.Add($"{root}:Animate:Interval must be more than 0; it is {animate.Interval}.");
            }
        }

        if (options.Turnaround < TimeSpan.Zero)
        {
            failures.Add($"{root}:Turnaround cannot be negative.");
        }

        try
        {
            options.Faults?.Validate();
        }
        catch (ArgumentException e)
        {
            failures.Add($"{root}:Faults:{e.ParamName}: {ErrorText.Of(e)}");
        }
    }
}
