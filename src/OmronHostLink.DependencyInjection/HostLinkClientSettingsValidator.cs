using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.Options;

namespace OmronHostLink.DependencyInjection;

/// <summary>
/// Checks a registered client's settings when the host starts (<see cref="HostLinkClientSettings.Validate"/>) and
/// reports every problem at once, each starting with the configuration path of its key
/// (<c>HostLink:Clients:line1:Serial:BaudRate: 12345 is not a standard rate …</c>), or with the client's name when it
/// was set in code.
/// </summary>
internal sealed class HostLinkClientSettingsValidator : IValidateOptions<HostLinkClientSettings>
{
    private readonly IEnumerable<HostLinkClientSource> _sources;

    public HostLinkClientSettingsValidator(IEnumerable<HostLinkClientSource> sources) => _sources = sources;

    public ValidateOptionsResult Validate(string? name, HostLinkClientSettings options)
    {
        HostLinkClientSource? source = _sources.LastOrDefault(s => s.OptionsName == name);
        if (source is null || options is null)
        {
            return ValidateOptionsResult.Skip;
        }

        string? path = source.Configuration is null ? null : (source.Configuration as IConfigurationSection)?.Path ?? "";
        if (source.Configuration is IConfigurationSection { } section && !section.Exists())
        {
            return ValidateOptionsResult.Fail($"{path}: the section is missing or empty; check the client's name and write Serial:PortName or Tcp in it");
        }

        IReadOnlyList<HostLinkSettingsProblem> problems = options.Validate();
        return problems.Count == 0
            ? ValidateOptionsResult.Success
            : ValidateOptionsResult.Fail(problems.Select(p => Describe(path, source.ClientName, p)));
    }

    /// <summary>
    /// <c>HostLink:Clients:line1:Serial:BaudRate: …</c> for configuration; <c>Host Link client "line1": Serial:BaudRate: …</c>
    /// for settings made in code only.
    /// </summary>
    private static string Describe(string? configurationPath, string? name, HostLinkSettingsProblem problem)
    {
        if (configurationPath is null)
        {
            string client = string.IsNullOrEmpty(name) ? "The default Host Link client" : $"Host Link client \"{name}\"";
            return $"{client}: {problem}";
        }

        string path = configurationPath.Length == 0 || problem.Key.Length == 0
            ? configurationPath + problem.Key
            : configurationPath + ":" + problem.Key;
        return path.Length == 0 ? problem.Message : $"{path}: {problem.Message}";
    }
}

/// <summary>Where a registered client's settings come from: its configuration section, or code only (null).</summary>
internal sealed class HostLinkClientSource
{
    public HostLinkClientSource(string optionsName, string? clientName, IConfiguration? configuration)
    {
        OptionsName = optionsName;
        ClientName = clientName;
        Configuration = configuration;
    }

    public string OptionsName { get; }

    public string? ClientName { get; }

    public IConfiguration? Configuration { get; }
}
