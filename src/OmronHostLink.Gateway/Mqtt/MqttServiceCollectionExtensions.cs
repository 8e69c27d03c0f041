using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using MQTTnet;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Queue;
using OmronHostLink.Gateway.Writes;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>Registers the MQTT output when the configuration has an enabled <c>Mqtt</c> section.</summary>
internal static class MqttServiceCollectionExtensions
{
    /// <summary>
    /// Adds the <c>Mqtt</c> section's check (a misspelt key is named even with the output off) and, when the section is
    /// there and its <c>Enabled</c> is not false, the MQTT output: its rule for the links' and groups' names and the
    /// writable rule, the tag sink the links report to, the gateway hosted service. Otherwise no MQTT client is ever
    /// made, and the worker only logs. Call it before the polling service is added, so that the gateway stops after the
    /// links and can send their last states.
    /// </summary>
    public static IServiceCollection AddMqttOutput(this IServiceCollection services, GatewayConfiguration gateway, string contentRoot)
    {
        ArgumentNullException.ThrowIfNull(gateway);
        new MqttOptionsValidator(gateway, contentRoot).AddTo(services);
        if (!gateway.IsEnabled(MqttOptions.SectionName))
        {
            return services;
        }

        gateway.AddGroupRule(new MqttTopicNames());
        gateway.AddGroupRule(new WritableRule());
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
        services.AddSingleton<MqttGateway>();
        services.AddHostedService(sp => sp.GetRequiredService<MqttGateway>());
        services.AddHostedService<StatisticsPublisher>();
        return services;
    }
}
