using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Simulation;

/// <summary>Checks the <c>Simulator</c> section when the simulator is enabled, naming bad fields by path.</summary>
public sealed class SimulatorOptionsValidator : IValidateOptions<SimulatorOptions>
{
    private readonly IConfiguration? _configuration;

    /// <summary>Checks the bound options only.</summary>
    public SimulatorOptionsValidator()
    {
    }

    /// <summary>Checks the section as written first (<see cref="ConfigurationSchema"/>), then the bound options.</summary>
    /// <param name="configuration">The configuration the options are bound from.</param>
    public SimulatorOptionsValidator(IConfiguration configuration)
    {
        _configuration = configuration;
    }

    /// <inheritdoc/>
    public ValidateOptionsResult Validate(string? name, SimulatorOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        if (_configuration is not null
            && ConfigurationSchema.Check(_configuration.GetSection(SimulatorOptions.SectionName), typeof(SimulatorOptions)) is { Count: > 0 } written)
        {
            return ValidateOptionsResult.Fail(written);
        }

        if (!options.Enabled)
        {
            return ValidateOptionsResult.Success;
        }

        const string root = SimulatorOptions.SectionName;
        var failures = new List<string>();
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
            failures.Add($"{root}:Faults:{e.ParamName}: {e.Message}");
        }

        return failures.Count == 0 ? ValidateOptionsResult.Success : ValidateOptionsResult.Fail(failures);
    }
}
