using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Outputs;

/// <summary>What every output shares, registered once however many outputs ask for it.</summary>
internal static class OutputServiceCollectionExtensions
{
    /// <summary>
    /// Adds the <see cref="TagCatalog"/> and <see cref="OpenLinks"/> (itself an output, so that it learns the links'
    /// clients), unless they are added already. An output that reads the catalogue or writes calls this.
    /// </summary>
    public static IServiceCollection AddOutputServices(this IServiceCollection services)
    {
        if (services.Any(d => d.ServiceType == typeof(OpenLinks)))
        {
            return services;
        }

        services.AddSingleton(sp => new TagCatalog(sp.GetRequiredService<IOptions<GatewayOptions>>().Value));
        services.AddSingleton<OpenLinks>();
        services.AddSingleton<ITagOutput>(sp => sp.GetRequiredService<OpenLinks>());
        return services;
    }
}
