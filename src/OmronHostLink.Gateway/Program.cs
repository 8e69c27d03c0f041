using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway;

// Ctrl+C, SIGTERM (systemctl stop) and a Windows service stop all end here through the host's lifetime.
HostApplicationBuilder builder = GatewayHost.CreateBuilder(args);
using IHost host = builder.Build();
try
{
    await host.RunAsync();
    return 0;
}
catch (Exception e) when (Unwrap(e) is { Count: > 0 } failures)
{
    Console.Error.WriteLine("OmronHostLink.Gateway: the configuration is not valid:");
    foreach (string failure in failures)
    {
        Console.Error.WriteLine("  - " + failure);
    }

    return 2;
}

static List<string> Unwrap(Exception e) => e switch
{
    OptionsValidationException v => v.Failures.ToList(),
    AggregateException a => a.InnerExceptions.SelectMany(Unwrap).ToList(),
    _ => [],
};
