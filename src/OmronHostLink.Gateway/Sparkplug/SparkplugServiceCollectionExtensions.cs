using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Writes;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>Registers the Sparkplug B output when the configuration has an enabled <c>Sparkplug</c> section.</summary>
internal static class SparkplugServiceCollectionExtensions
{
    /// <summary>
    /// Adds the <c>Sparkplug</c> section's check (a misspelt key is named even with the output off) and, when the
    /// section is there and its <c>Enabled</c> is not false, the Sparkplug B edge node: its rule for the links' and
    /// groups' names and the writable rule, the node the links report to, the DCMD processor and the MQTT session.
    /// Call it before the polling service is added, so that the edge node stops after the links and can send their
    /// devices' deaths before its own.
    /// </summary>
    public static IServiceCollection AddSparkplugOutput(this IServiceCollection services, GatewayConfiguration gateway)
    {
        ArgumentNullException.ThrowIfNull(gateway);
        new SparkplugOptionsValidator(gateway).AddTo(services);
        if (!gateway.IsEnabled(SparkplugOptions.SectionName))
        {
            return services;
        }

        gateway.AddGroupRule(new SparkplugNames());
        gateway.AddGroupRule(new WritableRule());
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
