using System.Diagnostics;

namespace OmronHostLink.Gateway.Tests.Telemetry;

/// <summary>
/// <c>OmronHostLink.Gateway</c> (from beside the test assembly) as a separate process, configured by command-line
/// arguments only: it runs in an empty working directory, so no appsettings.json is read.
/// </summary>
internal sealed class GatewayProcess : ProgramProcess
{
    private GatewayProcess(ProcessStartInfo start, string directory)
        : base(start, ownedDirectory: directory)
    {
    }

    /// <summary>The gateway assembly beside the test assembly.</summary>
    public static string Assembly => Path.Combine(AppContext.BaseDirectory, "OmronHostLink.Gateway.dll");

    public static GatewayProcess Start(IEnumerable<string> args, IReadOnlyDictionary<string, string>? environment = null)
    {
        string directory = NewDirectory("ohl-worker-");
        ProcessStartInfo start = DotnetStart(Assembly, args);
        start.WorkingDirectory = directory;
        start.Environment["DOTNET_ENVIRONMENT"] = "Production";
        foreach ((string name, string value) in environment ?? new Dictionary<string, string>())
        {
            start.Environment[name] = value;
        }

        var gateway = new GatewayProcess(start, directory);
        gateway.Launch();
        return gateway;
    }
}
