using System.Runtime.CompilerServices;
using Microsoft.Extensions.DependencyInjection;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Status;

/// <summary>Registers the status page when the configuration has an enabled <c>Status</c> section.</summary>
internal static class StatusServiceCollectionExtensions
{
    /// <summary>
    /// Adds the <c>Status</c> section's check (a misspelt key is named even with the page off) and, when the section is
    /// there and its <c>Enabled</c> is not false, the page: the stores it reads (each an output of its own, so they learn
    /// what the links report) and the server. Otherwise nothing of it is made or loaded, and nothing listens.
    /// </summary>
    public static IServiceCollection AddStatusPage(this IServiceCollection services, GatewayConfiguration gateway)
    {
        ArgumentNullException.ThrowIfNull(gateway);
        new StatusOptionsValidator(gateway).AddTo(services);
        if (gateway.IsEnabled(StatusOptions.SectionName))
        {
            AddPage(services);
        }

        return services;
    }

    /// <summary>Kept out of <see cref="AddStatusPage"/>, so that a gateway without the page never compiles (or loads) what it uses.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void AddPage(IServiceCollection services)
    {
        services.AddSingleton<TagBoard>();
        services.AddSingleton<ITagOutput>(sp => sp.GetRequiredService<TagBoard>());
        services.AddSingleton<UnitTimeline>();
        services.AddSingleton<ITagOutput>(sp => sp.GetRequiredService<UnitTimeline>());
        services.AddSingleton<LineTraces>();
        services.AddSingleton<ITagOutput>(sp => sp.GetRequiredService<LineTraces>());
        services.AddSingleton<TransactionRates>();
        services.AddSingleton<LinesView>();
        services.AddSingleton<OutputsView>();
        services.AddSingleton<StatusServer>();
        services.AddHostedService(sp => sp.GetRequiredService<StatusServer>());
    }
}
