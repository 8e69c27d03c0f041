using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Samples.Worker;

// A worker that polls PLC registers and logs them. Clients come from "HostLink:Clients" (OmronHostLink.DependencyInjection),
// what each client watches from "Watch". Ctrl+C, SIGTERM (systemctl stop) and a Windows service stop end it gracefully.
HostApplicationBuilder builder = Host.CreateApplicationBuilder(args);
builder.Services.AddHostLinkClients(builder.Configuration.GetSection("HostLink:Clients"));
builder.Services.AddOptions<WatchList>().BindConfiguration("Watch").ValidateOnStart();
builder.Services.AddSingleton<IValidateOptions<WatchList>, WatchListValidator>();
builder.Services.AddHostedService<RegisterLogger>();

// Each is inactive unless its service manager started the process.
builder.Services.AddWindowsService(o => o.ServiceName = "OmronHostLink.Worker");
builder.Services.AddSystemd();

using IHost host = builder.Build();
try
{
    // Validated before the host starts, so that a mistake is these lines only, not the host's failure log as well.
    host.Services.GetService<IStartupValidator>()?.Validate();
}
catch (Exception e) when (e is OptionsValidationException or AggregateException)
{
    // Every configuration problem at once, each naming its key; exit code 2 tells a service manager not to retry.
    Console.Error.WriteLine("OmronHostLink.Worker: the configuration is not valid:");
    IEnumerable<Exception> all = e is AggregateException a ? a.InnerExceptions : [e];
    foreach (string failure in all.OfType<OptionsValidationException>().SelectMany(v => v.Failures))
    {
        Console.Error.WriteLine("  - " + failure);
    }

    return 2;
}

await host.RunAsync();
return 0;
