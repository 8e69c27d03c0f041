using Microsoft.Extensions.DependencyInjection;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Statistics;

/// <summary>Registers the <see cref="LinkStatistics"/>.</summary>
internal static class StatisticsServiceCollectionExtensions
{
    /// <summary>
    /// Adds the <see cref="LinkStatistics"/>, an output of its own (it learns the units' states), with its demotion
    /// instruments. The MQTT output publishes its figures; without MQTT they are still metrics.
    /// </summary>
    public static IServiceCollection AddLinkStatistics(this IServiceCollection services)
    {
        services.AddSingleton<LinkStatistics>();
        services.AddSingleton<ITagOutput>(sp => sp.GetRequiredService<LinkStatistics>());
        return services;
    }
}
