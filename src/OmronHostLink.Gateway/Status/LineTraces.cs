using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// The line traces, off unless asked for: a link's frames are taken (its <see cref="ClientFrameTap"/> attached) only
/// while at least one page watches its trace, and the tap is removed when the last one stops. An output of its own,
/// to learn each link's client.
/// </summary>
internal sealed class LineTraces : ITagOutput
{
    private readonly Dictionary<string, LinkTrace> _links = new(StringComparer.Ordinal);
    private readonly TimeProvider _time;
    private readonly ILogger _logger;

    /// <summary>A trace for every enabled link, each off.</summary>
    /// <param name="gateway">The validated <c>HostLink</c> section.</param>
    /// <param name="options">The <c>Status</c> section (how many frames a trace keeps).</param>
    /// <param name="time">The clock of the frames' times.</param>
    /// <param name="logger">Where tracing on and off is logged.</param>
    public LineTraces(IOptions<GatewayOptions> gateway, IOptions<StatusOptions> options, TimeProvider time, ILogger<LineTraces> logger)
    {
        ArgumentNullException.ThrowIfNull(gateway);
        ArgumentNullException.ThrowIfNull(options);
        _time = time;
        _logger = logger;
        foreach (string link in gateway.Value.Links.Where(l => l.Value.Enabled).Select(l => l.Key))
        {
            _links.Add(link, new LinkTrace(new LineTrace(options.Value.TraceFrames)));
        }
    }

    /// <summary>The links that can be traced, by name.</summary>
    public IReadOnlyList<string> Links
    {
        get
        {
            lock (_links)
            {
                return _links.Keys.Order(StringComparer.Ordinal).ToList();
            }
        }
    }

    /// <summary>Whether a link's frames are being taken now.</summary>
    public bool IsTracing(string link)
    {
        lock (_links)
        {
            return _links.TryGetValue(link, out LinkTrace? trace) && trace.Tap is not null;
        }
    }

    /// <summary>The trace of <paramref name="link"/>; null for a link that is not configured.</summary>
    public LineTrace? Trace(string link)
    {
        lock (_links)
        {
            return _links.TryGetValue(link, out LinkTrace? trace) ? trace.Frames : null;
        }
    }

    /// <summary>
    /// Watches <paramref name="link"/>'s trace until the result is disposed: its frames are taken meanwhile (from when
    /// the link is polled). Null for a link that is not configured.
    /// </summary>
    public IDisposable? Watch(string link)
    {
        lock (_links)
        {
            if (!_links.TryGetValue(link, out LinkTrace? trace))
            {
                return null;
            }

            if (trace.Watchers++ == 0)
            {
                Attach(link, trace);
            }

            return new Watching(this, link);
        }
    }

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client)
    {
        lock (_links)
        {
            if (!_links.TryGetValue(link, out LinkTrace? trace))
            {
                return;
            }

            trace.Tap?.Dispose();
            trace.Tap = null;
            trace.Client = client as HostLinkClient;
            if (trace.Watchers > 0)
            {
                Attach(link, trace);
            }
        }
    }

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
        if (state != LinkState.Offline)
        {
            return;
        }

        lock (_links)
        {
            if (_links.TryGetValue(link, out LinkTrace? trace))
            {
                trace.Tap?.Dispose();
                trace.Tap = null;
                trace.Client = null;
            }
        }
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
    }

    private void Attach(string link, LinkTrace trace)
    {
        if (trace.Client is { } client)
        {
            trace.Tap = ClientFrameTap.Attach(client, _time, trace.Frames.Add);
            StatusLog.TraceOn(_logger, link);
        }
    }

    private void Unwatch(string link)
    {
        lock (_links)
        {
            if (_links.TryGetValue(link, out LinkTrace? trace) && --trace.Watchers == 0 && trace.Tap is not null)
            {
                trace.Tap.Dispose();
                trace.Tap = null;
                trace.Frames.Paused();
                StatusLog.TraceOff(_logger, link);
            }
        }
    }

    private sealed class LinkTrace(LineTrace frames)
    {
        public LineTrace Frames { get; } = frames;

        public HostLinkClient? Client { get; set; }

        public ClientFrameTap? Tap { get; set; }

        public int Watchers { get; set; }
    }

    private sealed class Watching(LineTraces owner, string link) : IDisposable
    {
        private int _disposed;

        public void Dispose()
        {
            if (Interlocked.Exchange(ref _disposed, 1) == 0)
            {
                owner.Unwatch(link);
            }
        }
    }
}
