using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway;

/// <summary>
/// The gateway's entry point: reads and checks the whole configuration before anything starts, and reports every
/// problem of every section at once, each naming its key (or its file and line), with exit code 2 and no stack trace.
/// </summary>
public static class GatewayProgram
{
    /// <summary>The command-line switch that writes each link's plan (its scan classes and their reads) and exits.</summary>
    internal const string PlanSwitch = "--plan";

    /// <summary>Runs the gateway until it is stopped (Ctrl+C, SIGTERM, a Windows service stop).</summary>
    /// <param name="args">The command line: configuration overrides such as <c>--Mqtt:Host=broker</c>.</param>
    /// <param name="error">Where configuration problems are written (the console's error stream).</param>
    /// <returns>The process's exit code.</returns>
    public static async Task<int> RunAsync(string[] args, TextWriter error)
    {
        ArgumentNullException.ThrowIfNull(error);
        ArgumentNullException.ThrowIfNull(args);

        // --plan: the configuration checked as for a start, then each link's plan written out; no PLC is asked.
        bool planOnly = args.Contains(PlanSwitch, StringComparer.OrdinalIgnoreCase);
        args = [.. args.Where(a => !a.Equals(PlanSwitch, StringComparison.OrdinalIgnoreCase))];
        HostApplicationBuilder builder;
        try
        {
            builder = GatewayHost.CreateBuilder(args);
        }
        catch (Exception e) when (ConfigurationPreflight.LoadProblem(e) is { } problem)
        {
            return Invalid(error, [problem]);
        }

        List<string> problems = ConfigurationPreflight.Check(builder.Configuration, GatewayHost.Sections);
        if (ConfigurationPreflight.BadLogLevels(builder.Configuration) is { Count: > 0 } badLevels)
        {
            // Reported above; a valid level in their place lets the host be built and every other section be checked.
            builder.Configuration.AddInMemoryCollection(badLevels.Select(k => new KeyValuePair<string, string?>(k, "Information")));
        }

        using IHost host = builder.Build();
        try
        {
            // The host would run this when it starts, but would log its failure with the framework's stack trace first.
            host.Services.GetService<IStartupValidator>()?.Validate();
        }
        catch (Exception e) when (Failures(e) is { Count: > 0 } failures)
        {
            problems.AddRange(failures.Where(f => !problems.Contains(f)));
        }
        catch (InvalidOperationException) when (problems.Count > 0)
        {
            // A value the framework cannot convert (a log level) is among the problems found already.
        }

        if (problems.Count > 0)
        {
            return Invalid(error, problems);
        }

        if (planOnly)
        {
            await Polling.ScanPlanReport.WriteAsync(host.Services.GetRequiredService<IOptions<GatewayOptions>>().Value, Console.Out).ConfigureAwait(false);
            return 0;
        }

        CancellationToken stopping = host.Services.GetRequiredService<IHostApplicationLifetime>().ApplicationStopping;
        try
        {
            await host.RunAsync().ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (stopping.IsCancellationRequested)
        {
            // Stopped (SIGTERM, Ctrl+C, a service stop) before it had finished starting: a stop like any other, not a
            // crash for the service manager to restart.
        }

        return Environment.ExitCode;
    }

    private static int Invalid(TextWriter error, IEnumerable<string> problems)
    {
        error.WriteLine("OmronHostLink.Gateway: the configuration is not valid:");
        foreach (string problem in problems)
        {
            error.WriteLine("  - " + problem);
        }

        return ExitCodes.InvalidConfiguration;
    }

    private static List<string> Failures(Exception e) => e switch
    {
        OptionsValidationException v => v.Failures.ToList(),
        AggregateException a => a.InnerExceptions.SelectMany(Failures).ToList(),
        _ => [],
    };
}
