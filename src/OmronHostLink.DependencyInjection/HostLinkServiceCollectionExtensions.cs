using System.Diagnostics.Metrics;
using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection.Extensions;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink;
using OmronHostLink.DependencyInjection;

namespace Microsoft.Extensions.DependencyInjection;

/// <summary>
/// Registers <see cref="HostLinkClient"/>s in a service collection: named clients as keyed services
/// (<c>[FromKeyedServices("line1")] HostLinkClient plc</c>), or one default client. Each client is a singleton created
/// on first use, logs through the container's <c>ILoggerFactory</c>, measures through its <c>IMeterFactory</c> (a
/// named client's metrics and spans carry its name as <c>hostlink.link.name</c>), and is closed when the container is
/// disposed.
/// Its settings are the library's <see cref="HostLinkClientSettings"/>, read from configuration by
/// <see cref="HostLinkClientSettings.Read"/> and checked when the host starts by <see cref="HostLinkClientSettings.Validate"/>:
/// every problem is reported at once, named by its configuration key.
/// </summary>
/// <example>
/// <code>
/// // appsettings.json: { "HostLink": { "Clients": { "line1": { "Serial": { "PortName": "/dev/ttyUSB0" } } } } }
/// builder.Services.AddHostLinkClients(builder.Configuration.GetSection("HostLink:Clients"));
/// // or one at a time:
/// builder.Services.AddHostLinkClient("line2", o => o.Tcp.Host = "192.0.2.10");
/// </code>
/// </example>
public static class HostLinkServiceCollectionExtensions
{
    /// <summary>Registers a client named <paramref name="name"/>, read from a configuration section.</summary>
    /// <param name="services">The service collection.</param>
    /// <param name="name">The client's name: its service key and its options name.</param>
    /// <param name="configuration">The client's section, e.g. <c>HostLink:Clients:line1</c>.</param>
    /// <param name="configure">Changes applied after the configuration is read, or null.</param>
    /// <returns>The service collection.</returns>
    /// <exception cref="ArgumentException"><paramref name="name"/> is empty.</exception>
    /// <exception cref="InvalidOperationException">A client with that name is registered already.</exception>
    public static IServiceCollection AddHostLinkClient(
        this IServiceCollection services, string name, IConfiguration configuration, Action<HostLinkClientSettings>? configure = null)
    {
        CheckName(name);
        NotNull(configuration, nameof(configuration));
        return Add(services, name, configuration, configure);
    }

    /// <summary>Registers a client named <paramref name="name"/>, set in code.</summary>
    /// <param name="services">The service collection.</param>
    /// <param name="name">The client's name: its service key and its options name.</param>
    /// <param name="configure">Sets the client's link and options.</param>
    /// <returns>The service collection.</returns>
    /// <exception cref="ArgumentException"><paramref name="name"/> is empty.</exception>
    /// <exception cref="InvalidOperationException">A client with that name is registered already.</exception>
    public static IServiceCollection AddHostLinkClient(this IServiceCollection services, string name, Action<HostLinkClientSettings> configure)
    {
        CheckName(name);
        NotNull(configure, nameof(configure));
        return Add(services, name, null, configure);
    }

    /// <summary>
    /// Registers one named client for each child of <paramref name="clients"/> (such as <c>HostLink:Clients</c>), named
    /// by the child's key.
    /// </summary>
    /// <param name="services">The service collection.</param>
    /// <param name="clients">The section whose children are the clients.</param>
    /// <returns>The service collection.</returns>
    /// <exception cref="InvalidOperationException">The section holds no client, or a name is registered already.</exception>
    public static IServiceCollection AddHostLinkClients(this IServiceCollection services, IConfiguration clients)
    {
        NotNull(services, nameof(services));
        NotNull(clients, nameof(clients));
        IConfigurationSection[] children = clients.GetChildren().ToArray();
        if (children.Length == 0)
        {
            string where = clients is IConfigurationSection s ? $"Configuration section '{s.Path}'" : "The configuration";
            throw new InvalidOperationException($"{where} holds no Host Link client; write one section per client under it, e.g. \"line1\": {{ \"Serial\": {{ \"PortName\": \"COM3\" }} }}.");
        }

        foreach (IConfigurationSection child in children)
        {
            Add(services, child.Key, child, null);
        }

        return services;
    }

    /// <summary>
    /// Registers the default client, resolved without a key (<c>HostLinkClient plc</c>), read from a configuration
    /// section. Registering named clients never registers a default one: what an unkeyed <see cref="HostLinkClient"/>
    /// means does not change when a second link is added.
    /// </summary>
    /// <param name="services">The service collection.</param>
    /// <param name="configuration">The client's section, e.g. <c>HostLink:Client</c>.</param>
    /// <param name="configure">Changes applied after the configuration is read, or null.</param>
    /// <returns>The service collection.</returns>
    /// <exception cref="InvalidOperationException">A default client is registered already.</exception>
    public static IServiceCollection AddHostLinkClient(
        this IServiceCollection services, IConfiguration configuration, Action<HostLinkClientSettings>? configure = null)
    {
        NotNull(configuration, nameof(configuration));
        return Add(services, null, configuration, configure);
    }

    /// <summary>Registers the default client, resolved without a key (<c>HostLinkClient plc</c>), set in code.</summary>
    /// <param name="services">The service collection.</param>
    /// <param name="configure">Sets the client's link and options.</param>
    /// <returns>The service collection.</returns>
    /// <exception cref="InvalidOperationException">A default client is registered already.</exception>
    public static IServiceCollection AddHostLinkClient(this IServiceCollection services, Action<HostLinkClientSettings> configure)
    {
        NotNull(configure, nameof(configure));
        return Add(services, null, null, configure);
    }

    private static IServiceCollection Add(IServiceCollection services, string? name, IConfiguration? configuration, Action<HostLinkClientSettings>? configure)
    {
        NotNull(services, nameof(services));
        bool registered = services.Any(d => d.ServiceType == typeof(HostLinkClient)
            && (name is null ? !d.IsKeyedService : d.IsKeyedService && Equals(d.ServiceKey, name)));
        if (registered)
        {
            throw new InvalidOperationException(name is null
                ? "A default Host Link client is registered already."
                : $"A Host Link client named '{name}' is registered already.");
        }

        string optionsName = name ?? Options.Options.DefaultName;
        OptionsBuilder<HostLinkClientSettings> options = services.AddOptions<HostLinkClientSettings>(optionsName);
        if (configuration is not null)
        {
            options.Configure(s => s.Read(configuration.AsEnumerable(makePathsRelative: true)));
        }

        if (configure is not null)
        {
            options.Configure(configure);
        }

        options.ValidateOnStart();
        services.AddSingleton(new HostLinkClientSource(optionsName, name, configuration));
        services.TryAddEnumerable(ServiceDescriptor.Singleton<IValidateOptions<HostLinkClientSettings>, HostLinkClientSettingsValidator>());

        if (name is null)
        {
            services.AddSingleton(sp => Create(sp, optionsName, null));
        }
        else
        {
            services.AddKeyedSingleton(name, (sp, _) => Create(sp, optionsName, name));
        }

        return services;
    }

    /// <summary>
    /// The client the settings describe, logging through the container's logger factory and measuring through its meter
    /// factory (when it has them), named in metrics and traces by its registered name.
    /// </summary>
    private static HostLinkClient Create(IServiceProvider services, string optionsName, string? name)
    {
        // Throws OptionsValidationException, naming every problem, when the host was not started to check them.
        HostLinkClientSettings settings = services.GetRequiredService<IOptionsMonitor<HostLinkClientSettings>>().Get(optionsName);
        return settings.CreateClient(o =>
        {
            o.LoggerFactory = services.GetService<ILoggerFactory>();
            o.MeterFactory = services.GetService<IMeterFactory>();
            o.LinkName = name;
        });
    }

    private static void CheckName(string name)
    {
        NotNull(name, nameof(name));
        if (name.Trim().Length == 0)
        {
            throw new ArgumentException("A Host Link client's name must not be empty; use the overload without a name for the default client.", nameof(name));
        }
    }

    private static void NotNull(object? value, string parameter)
    {
        if (value is null)
        {
            throw new ArgumentNullException(parameter);
        }
    }
}
