using System.ComponentModel.DataAnnotations;
using Microsoft.Extensions.Configuration;
using OmronHostLink.Gateway.Simulation;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>The start-time validation, run ahead on a configuration: would the host start?</summary>
internal static class StartupCheck
{
    /// <summary>Whether both sections pass the checks the host runs when it starts.</summary>
    public static bool Passes(IConfiguration configuration)
    {
        IConfigurationSection hostLink = configuration.GetSection(GatewayOptions.SectionName);
        IConfigurationSection simulator = configuration.GetSection(SimulatorOptions.SectionName);
        if (ConfigurationSchema.Check(hostLink, typeof(GatewayOptions)).Count > 0
            || ConfigurationSchema.Check(simulator, typeof(SimulatorOptions)).Count > 0)
        {
            return false;
        }

        try
        {
            var worker = new GatewayOptions();
            LinkClients.Bind(hostLink, worker);
            var sim = new SimulatorOptions();
            ConfigurationSchema.Bind(simulator, sim);
            return new GatewayOptionsValidator().Validate(null, worker).Succeeded
                && new SimulatorOptionsValidator().Validate(null, sim).Succeeded
                && Validator.TryValidateObject(sim, new ValidationContext(sim), null, validateAllProperties: true);
        }
        catch (InvalidOperationException)
        {
            return false;
        }
    }
}
