using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using MQTTnet;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>Registers the MQTT output when the configuration has an enabled <c>Mqtt</c> section.</summary>
public static class MqttServiceCollectionExtensions
{
    /// <summary>
    /// Adds the MQTT output (options and their validation, the tag sink the links report to, the gateway hosted
    /// service) if <paramref name="configuration"/> has a <c>Mqtt</c> section whose <c>Enabled</c> is not false.
    /// Otherwise adds nothing: no MQTT client is ever made, and the worker only logs. Call it before the polling
    /// service is added, so that the gateway stops after the links and can send their last states.
    /// </summary>
    public static IServiceCollection AddMqttOutput(this IServiceCollection services, IConfiguration configuration)
    {
        ArgumentNullException.ThrowIfNull(configuration);
        IConfigurationSection section = configuration.GetSection(MqttOptions.SectionName);
        if (!section.Exists() || (bool.TryParse(section[nameof(MqttOptions.Enabled)], out bool enabled) && !enabled))
        {
            return services;
        }

        services.AddOptions<MqttOptions>().Configure(o => ConfigurationSchema.Bind(section, o)).ValidateOnStart();
        services.AddSingleton<IValidateOptions<MqttOptions>>(sp => new MqttOptionsValidator(configuration, sp.GetRequiredService<IHostEnvironment>().ContentRootPath));
        services.AddOutputServices();
        services.AddSingleton(sp =>
        {
            MqttOptions o = sp.GetRequiredService<IOptions<MqttOptions>>().Value;
            return new MqttTopics(o.TopicPrefix, o.ClientIdOrDefault);
        });
        services.AddSingleton(sp => MqttOutboundQueue.OpenStore(
            sp.GetRequiredService<IOptions<MqttOptions>>().Value,
            sp.GetRequiredService<IHostEnvironment>().ContentRootPath,
            sp.GetRequiredService<ILogger<OutboundQueue>>()));
        services.AddSingleton(sp => sp.GetRequiredService<OutboundQueueStore>().CreateQueue(
            sp.GetRequiredService<IOptions<MqttOptions>>().Value,
            sp.GetRequiredService<MqttTopics>(),
            sp.GetRequiredService<TimeProvider>()));
        services.AddSingleton<MqttMetrics>();
        services.AddSingleton<MqttTagSink>();
        services.AddSingleton<ITagOutput>(sp => sp.GetRequiredService<MqttTagSink>());
        services.AddSingleton<MqttClientFactory>();
        services.AddSingleton(sp => new WriteCommandProcessor(
            sp.GetRequiredService<IOptions<MqttOptions>>().Value,
            sp.GetRequiredService<MqttTopics>(),
            sp.GetRequiredService<TagCatalog>(),
            sp.GetRequiredService<OpenLinks>(),
            sp.GetRequiredService<OutboundQueue>(),
            sp.GetRequiredService<MqttMetrics>(),
            sp.GetRequiredService<ILogger<WriteCommandProcessor>>(),
            sp.GetRequiredService<TimeProvider>()));
        services.AddSingleton<IValidateOptions<MqttOptions>, StatisticsIntervalValidator>();
        services.AddSingleton<MqttGateway>();
        services.AddHostedService(sp => sp.GetRequiredService<MqttGateway>());
        services.AddHostedService<StatisticsPublisher>();
        return services;
    }
}
