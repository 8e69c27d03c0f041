using System.Text;
using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;

namespace OmronHostLink.DependencyInjection.Tests;

/// <summary>A generic host whose only configuration is the JSON text given, as an application's appsettings.json.</summary>
internal sealed class JsonHost : IAsyncDisposable
{
    private JsonHost(IHost host, CapturingLoggerProvider logs)
    {
        Host = host;
        Logs = logs;
    }

    public IHost Host { get; }

    public IServiceProvider Services => Host.Services;

    public CapturingLoggerProvider Logs { get; }

    /// <summary>Builds (does not start) a host from <paramref name="json"/>; <paramref name="register"/> adds the clients.</summary>
    public static JsonHost Build(string json, Action<IServiceCollection, IConfiguration> register)
    {
        HostApplicationBuilder builder = Microsoft.Extensions.Hosting.Host.CreateApplicationBuilder(new HostApplicationBuilderSettings
        {
            DisableDefaults = true,
            EnvironmentName = "Test",
            ContentRootPath = AppContext.BaseDirectory,
        });
        builder.Configuration.AddJsonStream(new MemoryStream(Encoding.UTF8.GetBytes(json)));
        var logs = new CapturingLoggerProvider();
        builder.Logging.SetMinimumLevel(LogLevel.Debug);
        builder.Logging.AddProvider(logs);
        register(builder.Services, builder.Configuration);
        return new JsonHost(builder.Build(), logs);
    }

    /// <summary>Starts a host that must fail validation, and returns every problem it reported.</summary>
    public static async Task<IReadOnlyList<string>> StartFailuresAsync(string json, Action<IServiceCollection, IConfiguration> register)
    {
        await using JsonHost host = Build(json, register);
        Exception? failure = null;
        try
        {
            await host.Host.StartAsync();
        }
        catch (Exception e)
        {
            failure = e;
        }

        failure.Should().NotBeNull("the host must not start with this configuration");
        return Failures(failure!);
    }

    /// <summary>The validation failures in an exception from start: one OptionsValidationException per client, or several together.</summary>
    public static IReadOnlyList<string> Failures(Exception e) => e switch
    {
        OptionsValidationException o => o.Failures.ToArray(),
        AggregateException a => a.InnerExceptions.SelectMany(Failures).ToArray(),
        _ => throw new Xunit.Sdk.XunitException($"Expected options validation to fail, but got {e}"),
    };

    public async ValueTask DisposeAsync()
    {
        await Host.StopAsync();
        if (Host is IAsyncDisposable d)
        {
            await d.DisposeAsync();
        }
        else
        {
            Host.Dispose();
        }
    }
}
