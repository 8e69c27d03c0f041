using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// The check of one configuration section, the same for every section: the section as written first (a misspelt key,
/// a value of the wrong type — whether the section is on or not), then, when it is on, the rules of its bound options.
/// Where the section as written has problems its bound options are not judged: they miss what could not be read, and
/// judging them would only add consequences of those problems. Each failure names its key. The verdict is kept by the
/// <see cref="GatewayConfiguration"/>: a section is judged once per host.
/// </summary>
/// <typeparam name="TOptions">The options class the section binds to.</typeparam>
/// <param name="gateway">The configuration as the gateway reads it.</param>
/// <param name="section">The section's key (<c>HostLink</c>, <c>Mqtt</c>, …).</param>
internal abstract class SectionValidator<TOptions>(GatewayConfiguration gateway, string section) : IValidateOptions<TOptions>
    where TOptions : class
{
    /// <summary>The configuration as the gateway reads it.</summary>
    protected GatewayConfiguration Gateway { get; } = gateway;

    /// <summary>The section's key.</summary>
    protected string Section { get; } = section;

    /// <inheritdoc/>
    public ValidateOptionsResult Validate(string? name, TOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        return Gateway.Verdict(Section, () =>
        {
            IReadOnlyList<string> written = Gateway.Written(Section, typeof(TOptions));
            if (written.Count > 0)
            {
                return ValidateOptionsResult.Fail(written);
            }

            if (!IsOn(options))
            {
                return ValidateOptionsResult.Success;
            }

            var failures = new List<string>();
            Check(options, failures);
            return failures.Count == 0 ? ValidateOptionsResult.Success : ValidateOptionsResult.Fail(failures);
        });
    }

    /// <summary>
    /// Registers the section's options, bound by <paramref name="bind"/> (by default from the section as written, with
    /// the library's duration grammar) and checked by this validator when the host starts.
    /// </summary>
    public void AddTo(IServiceCollection services, Action<TOptions>? bind = null)
    {
        services.AddSingleton<IValidateOptions<TOptions>>(this);
        services.AddOptions<TOptions>().Configure(bind ?? (o => Gateway.Bind(Section, o))).ValidateOnStart();
    }

    /// <summary>Whether the section is on, and its options are judged; by default always.</summary>
    protected virtual bool IsOn(TOptions options) => true;

    /// <summary>Adds the problems of the bound <paramref name="options"/> to <paramref name="failures"/>, each naming its key.</summary>
    protected abstract void Check(TOptions options, List<string> failures);
}
