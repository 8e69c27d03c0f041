using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;
using OmronHostLink.Planning;

namespace OmronHostLink.Samples.Worker;

/// <summary>Checks the <c>Watch</c> section at start-up: every client exists, every tag parses, every interval is sane.</summary>
internal sealed class WatchListValidator(IServiceProvider services) : IValidateOptions<WatchList>
{
    public ValidateOptionsResult Validate(string? name, WatchList options)
    {
        var failures = new List<string>();
        if (options.Count == 0)
        {
            failures.Add("Watch is empty: name a client of HostLink:Clients and its tags, e.g. \"Watch\": { \"line1\": { \"Tags\": [ \"D100:int16\" ] } }.");
        }

        IServiceProviderIsKeyedService keyed = services.GetRequiredService<IServiceProviderIsKeyedService>();
        foreach ((string client, WatchSettings watch) in options)
        {
            if (!keyed.IsKeyedService(typeof(HostLinkClient), client))
            {
                failures.Add($"Watch:{client} names no client: add HostLink:Clients:{client}.");
            }

            if (watch.Interval <= TimeSpan.Zero || watch.Interval > TimeSpan.FromDays(1))
            {
                failures.Add($"Watch:{client}:Interval {watch.Interval} is not between 0 and 1 day.");
            }

            if (watch.Tags.Count == 0)
            {
                failures.Add($"Watch:{client}:Tags is empty.");
            }

            for (int i = 0; i < watch.Tags.Count; i++)
            {
                try
                {
                    PlcTag.Parse(watch.Tags[i]);
                }
                catch (FormatException e)
                {
                    failures.Add($"Watch:{client}:Tags:{i}: {e.Message}");
                }
            }
        }

        return failures.Count == 0 ? ValidateOptionsResult.Success : ValidateOptionsResult.Fail(failures);
    }
}
