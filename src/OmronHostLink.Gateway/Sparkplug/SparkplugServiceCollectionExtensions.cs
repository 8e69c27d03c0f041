using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>Registers the Sparkplug B output when the configuration has an enabled <c>Sparkplug</c> section.</summary>
public static class SparkplugServiceCollectionExtensions
{
    /// <summary>
    /// Adds the Sparkplug B edge node (options and their validation, the node the links report to, the DCMD processor
    /// and the MQTT session) if <paramref name="configuration"/> has a <c>Sparkplug</c> section whose <c>Enabled</c> is
    /// not false; otherwise nothing. Call it before the polling service is added, so that the edge node stops after the
    /// links and can send their devices' deaths before its own.
    /// </summary>
    public static IServiceCollection AddSparkplugOutput(this IServiceCollection services, IConfiguration configuration)
    {
        ArgumentNullException.ThrowIfNull(configuration);
        IConfigurationSection section = configuration.GetSection(SparkplugOptions.SectionName);
        if (!section.Exists() || (bool.TryParse(section[nameof(SparkplugOptions.Enabled)], out bool enabled) && !enabled))
        {
            return services;
        }

        services.AddOptions<SparkplugOptions>().Configure(o => ConfigurationSchema.Bind(section, o)).ValidateOnStart();
        services.AddSingleton<IValidateOptions<SparkplugOptions>>(new SparkplugOptionsValidator(configuration));
        services.AddOutputServices();
        services.AddSingleton(sp => new SparkplugNode(
            sp.GetRequiredService<IOptions<SparkplugOptions>>().Value,
            sp.GetRequiredService<TagCatalog>(),
            sp.GetRequiredService<TimeProvider>()));
        services.AddSingleton<ITagOutput>(sp => sp.GetRequiredService<SparkplugNode>());
        services.AddSingleton(sp => new SparkplugCommands(
            sp.GetRequiredService<IOptions<SparkplugOptions>>().Value,
            sp.GetRequiredService<SparkplugNode>(),
            sp.GetRequiredService<OpenLinks>(),
            sp.GetRequiredService<System.Diagnostics.Metrics.IMeterFactory>(),
            sp.GetRequiredService<ILogger<SparkplugCommands>>()));
        services.AddSingleton<SparkplugEdgeNode>();
        services.AddHostedService(sp => sp.GetRequiredService<SparkplugEdgeNode>());
        return services;
    }
}
