using System.Net;
using System.Net.Sockets;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Hosting;
using Microsoft.AspNetCore.Hosting.Server;
using Microsoft.AspNetCore.Hosting.Server.Features;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using Microsoft.AspNetCore.Server.Kestrel.Core;
using Microsoft.AspNetCore.StaticFiles;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.FileProviders;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// Serves the status page inside the gateway's process and lifetime: an ASP.NET Core application of its own (Kestrel,
/// minimal APIs, the page's files embedded in the gateway) that starts when the gateway starts and stops when it stops,
/// on the configured address only. The gateway's host keeps the process's signals and service manager (Windows service,
/// systemd): the page's application has no lifetime of its own. Registered only when the <c>Status</c> section is on.
/// </summary>
internal sealed class StatusServer : IHostedService, IAsyncDisposable
{
    /// <summary>The most connections the page takes at once (each open page holds one stream).</summary>
    private const int MaxConnections = 64;

    private readonly StatusOptions _options;
    private readonly LinesView _lines;
    private readonly TagBoard _tags;
    private readonly OutputsView _outputs;
    private readonly LineTraces _traces;
    private readonly TimeProvider _time;
    private readonly ILoggerFactory _loggerFactory;
    private readonly ILogger _logger;
    private readonly IHostApplicationLifetime _lifetime;
    private readonly IHostEnvironment _environment;
    private WebApplication? _app;

    /// <summary>Creates the server; nothing listens until it is started.</summary>
    public StatusServer(
        IOptions<StatusOptions> options,
        LinesView lines,
        TagBoard tags,
        OutputsView outputs,
        LineTraces traces,
        TimeProvider time,
        ILoggerFactory loggerFactory,
        IHostApplicationLifetime lifetime,
        IHostEnvironment environment)
    {
        ArgumentNullException.ThrowIfNull(options);
        _options = options.Value;
        _lines = lines;
        _tags = tags;
        _outputs = outputs;
        _traces = traces;
        _time = time;
        _loggerFactory = loggerFactory;
        _logger = loggerFactory.CreateLogger<StatusServer>();
        _lifetime = lifetime;
        _environment = environment;
    }

    /// <summary>The address and port the page listens on, once started (<c>127.0.0.1:9680</c>).</summary>
    public IPEndPoint? EndPoint { get; private set; }

    /// <summary>The page's routes (the files and the API), once started.</summary>
    public IReadOnlyList<RouteEndpoint> Routes => _app is null
        ? []
        : ((IEndpointRouteBuilder)_app).DataSources.SelectMany(d => d.Endpoints).OfType<RouteEndpoint>().ToList();

    /// <inheritdoc/>
    public async Task StartAsync(CancellationToken cancellationToken)
    {
        IPAddress address = _options.IPAddress!;
        WebApplication app = Build(address);
        try
        {
            await app.StartAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (IOException e)
        {
            // One line, not the host's failure with two stack traces: another program has the port, or the address is
            // not one of this machine's.
            await app.DisposeAsync().ConfigureAwait(false);
            StatusLog.CannotListen(_logger, address.ToString(), _options.Port, Reason(e));
            Environment.ExitCode = ExitCodes.InvalidConfiguration;
            _lifetime.StopApplication();
            return;
        }

        _app = app;
        string bound = app.Services.GetRequiredService<IServer>().Features.Get<IServerAddressesFeature>()?.Addresses.FirstOrDefault() ?? "";
        EndPoint = Uri.TryCreate(bound, UriKind.Absolute, out Uri? uri) && IPAddress.TryParse(uri.Host.Trim('[', ']'), out IPAddress? ip) ? new IPEndPoint(ip, uri.Port) : new IPEndPoint(address, _options.Port);
        StatusLog.Started(_logger, EndPoint.ToString(), _options.HasToken ? "access token required" : "this machine only, no token");
    }

    /// <inheritdoc/>
    public async Task StopAsync(CancellationToken cancellationToken)
    {
        if (_app is null)
        {
            return;
        }

        await _app.StopAsync(cancellationToken).ConfigureAwait(false);
        await _app.DisposeAsync().ConfigureAwait(false);
        _app = null;
        StatusLog.Stopped(_logger);
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => _app?.DisposeAsync() ?? ValueTask.CompletedTask;

    private WebApplication Build(IPAddress address)
    {
        // Empty: no configuration sources (the gateway's are read once, by the gateway), no logging providers of its own
        // (it logs through the gateway's), no HTTPS, no lifetime of its own.
        WebApplicationBuilder builder = WebApplication.CreateEmptyBuilder(new WebApplicationOptions
        {
            ApplicationName = typeof(StatusServer).Assembly.GetName().Name,
            ContentRootPath = _environment.ContentRootPath,
            EnvironmentName = Environments.Production,
        });
        // Its logs go to the gateway's, but for its host's own start and stop: a failure to listen is reported by
        // StartAsync in one line, and the gateway's host reports its own start and stop.
        builder.Logging.AddProvider(new GatewayLogs(_loggerFactory));
        builder.Logging.AddFilter("Microsoft.Extensions.Hosting.Internal.Host", LogLevel.None);
        builder.Services.AddSingleton<IHostLifetime, GatewayOwnedLifetime>();
        builder.Services.AddRoutingCore();
        builder.WebHost.UseKestrelCore().ConfigureKestrel(kestrel =>
        {
            kestrel.AddServerHeader = false;
            kestrel.Limits.MaxConcurrentConnections = MaxConnections;
            // Nothing the page serves reads a body; one sent anyway is drained and dropped.
            kestrel.Limits.MaxRequestBodySize = 64 * 1024;
            kestrel.Listen(address, _options.Port, listen => listen.Protocols = HttpProtocols.Http1);
        });

        WebApplication app = builder.Build();
        var access = new StatusAccess(_options, _logger);
        app.Use(access.InvokeAsync);
        var files = new EmbeddedFileProvider(typeof(StatusServer).Assembly, typeof(StatusServer).Namespace + ".Assets");
        app.UseDefaultFiles(new DefaultFilesOptions { FileProvider = files });
        app.UseStaticFiles(new StaticFileOptions
        {
            FileProvider = files,
            ContentTypeProvider = new FileExtensionContentTypeProvider(),
            // Always asked again (answered 304 while unchanged): a new gateway's page is never an old one from the cache.
            OnPrepareResponse = f => f.Context.Response.Headers.CacheControl = "no-cache",
        });
        app.UseRouting();
        // Open pages' streams end when the application stops, which it does first thing when the gateway stops.
        var streams = new StatusStreams(_options, _lines, _tags, _outputs, _traces, _time, app.Lifetime.ApplicationStopping);
        StatusEndpoints.Map(app, _lines, _tags, _outputs, _traces, streams);
        return app;
    }

    private static string Reason(Exception e)
    {
        for (Exception? x = e; x is not null; x = x.InnerException)
        {
            if (x is SocketException socket)
            {
                return socket.Message;
            }
        }

        return e.Message;
    }

    /// <summary>The page's loggers are the gateway's (with the gateway's levels and providers).</summary>
    private sealed class GatewayLogs(ILoggerFactory gateway) : ILoggerProvider
    {
        public ILogger CreateLogger(string categoryName) => gateway.CreateLogger(categoryName);

        public void Dispose()
        {
        }
    }

    /// <summary>The page's application stops when the gateway's host tells it to, never on a signal of its own.</summary>
    private sealed class GatewayOwnedLifetime : IHostLifetime
    {
        public Task WaitForStartAsync(CancellationToken cancellationToken) => Task.CompletedTask;

        public Task StopAsync(CancellationToken cancellationToken) => Task.CompletedTask;
    }
}
