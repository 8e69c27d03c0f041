using Microsoft.Extensions.Options;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>Checks <c>Mqtt:StatisticsInterval</c>: 1 s to 1 h.</summary>
internal sealed class StatisticsIntervalValidator : IValidateOptions<MqttOptions>
{
    private static readonly TimeSpan Shortest = TimeSpan.FromSeconds(1);
    private static readonly TimeSpan Longest = TimeSpan.FromHours(1);

    public ValidateOptionsResult Validate(string? name, MqttOptions options)
        => !options.Enabled || (options.StatisticsInterval >= Shortest && options.StatisticsInterval <= Longest)
            ? ValidateOptionsResult.Success
            : ValidateOptionsResult.Fail($"{MqttOptions.SectionName}:StatisticsInterval must be 1s to 1h; it is {options.StatisticsInterval}.");
}
