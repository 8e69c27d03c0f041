using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Tests;

/// <summary>
/// The gateway's host as its program builds it (<see cref="GatewayHost.CreateBuilder"/>), from in-memory configuration
/// only: no appsettings.json, environment variables or command line, in the Test environment.
/// </summary>
internal static class TestGatewayHost
{
    /// <summary>A builder over <paramref name="config"/> alone.</summary>
    public static HostApplicationBuilder CreateBuilder(IEnumerable<KeyValuePair<string, string?>> config)
    {
        var configuration = new ConfigurationManager();
        configuration.AddInMemoryCollection(config);
        return GatewayHost.CreateBuilder(new HostApplicationBuilderSettings
        {
            DisableDefaults = true,
            EnvironmentName = "Test",
            ContentRootPath = AppContext.BaseDirectory,
            Configuration = configuration,
        });
    }

    /// <summary>
    /// A host over <paramref name="config"/> that logs from Debug up to <paramref name="logs"/> and gives its stop at most
    /// <paramref name="shutdownTimeout"/>; <paramref name="services"/> may add to it.
    /// </summary>
    public static IHost Build(IEnumerable<KeyValuePair<string, string?>> config, CapturingLoggerProvider logs, TimeSpan shutdownTimeout, Action<IServiceCollection>? services = null)
    {
        HostApplicationBuilder builder = CreateBuilder(config);
        builder.Logging.SetMinimumLevel(LogLevel.Debug);
        builder.Logging.AddProvider(logs);
        builder.Services.Configure<HostOptions>(o => o.ShutdownTimeout = shutdownTimeout);
        services?.Invoke(builder.Services);
        return builder.Build();
    }
}
