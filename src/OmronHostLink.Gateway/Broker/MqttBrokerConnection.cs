using MQTTnet;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// What every MQTT output keeps of its broker connection (<see cref="MqttBrokerOptions"/>): the client, the loops that
/// use it and their stop, the client options with the certificate check, the backoff between attempts and the end of
/// the connection. The output decides what is sent, when, and what is logged.
/// </summary>
internal sealed class MqttBrokerConnection : IAsyncDisposable
{
    private static readonly TimeSpan DropLimit = TimeSpan.FromSeconds(2);

    private readonly MqttBrokerOptions _options;
    private readonly string _section;
    private readonly TimeProvider _time;
    private readonly CancellationTokenSource _stop = new();
    private readonly List<Task> _loops = [];
    private TimeSpan _backoff;
    private volatile string? _certificateProblem;

    /// <summary>Makes the client; nothing connects until a loop does.</summary>
    /// <param name="options">The validated broker settings.</param>
    /// <param name="section">The section's key (<c>Mqtt</c>, <c>Sparkplug</c>).</param>
    /// <param name="factory">Makes the client.</param>
    /// <param name="time">Times the waits between attempts.</param>
    public MqttBrokerConnection(MqttBrokerOptions options, string section, MqttClientFactory factory, TimeProvider time)
    {
        _options = options;
        _section = section;
        _time = time;
        Client = factory.CreateMqttClient();
        Broker = $"{options.Host}:{options.PortOrDefault}";
    }

    /// <summary>The client.</summary>
    public IMqttClient Client { get; }

    /// <summary>The broker as the logs name it: <c>host:port</c>.</summary>
    public string Broker { get; }

    /// <summary>The loop that connects and sends, once started.</summary>
    public Task? ConnectionLoop { get; private set; }

    /// <summary>Whether the loops are told to stop.</summary>
    public bool IsStopping => _stop.IsCancellationRequested;

    /// <summary>How many attempts have failed since the last connection (or since the start).</summary>
    public int FailedAttempts { get; private set; }

    /// <summary>Starts the client options: the broker, credentials and TLS, a refused certificate remembered for <see cref="FailedAsync"/>.</summary>
    public MqttClientOptionsBuilder ClientOptions()
        => MqttClientOptionsFactory.Create(_options, _section, why => _certificateProblem = why);

    /// <summary>Starts the connection loop and the output's other loops, each given the token that stops them.</summary>
    /// <param name="connectionLoop">The loop that connects and sends (<see cref="ConnectionLoop"/>).</param>
    /// <param name="others">Loops that only end with the connection's (commands).</param>
    public void Start(Func<CancellationToken, Task> connectionLoop, params Func<CancellationToken, Task>[] others)
    {
        ConnectionLoop = Run(connectionLoop);
        foreach (Func<CancellationToken, Task> loop in others)
        {
            Run(loop);
        }
    }

    /// <summary>Tells the loops to stop, without waiting for them.</summary>
    public Task CancelAsync() => _stop.CancelAsync();

    /// <summary>Tells the loops to stop and waits until they have.</summary>
    public async Task StopLoopsAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        foreach (Task loop in _loops)
        {
            await loop.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        }
    }

    /// <summary>A connection is up: the next failure waits <see cref="BackoffOptions.Initial"/> again.</summary>
    public void Connected() => FailedAttempts = 0;

    /// <summary>
    /// After a failed attempt or a lost connection: closes what is left of the connection, counts the failure and says
    /// why it failed (a refused certificate's reason, otherwise <see cref="Describe"/>'s) and how long to wait
    /// (<see cref="Backoff"/>).
    /// </summary>
    public async Task<(string Reason, TimeSpan Delay)> FailedAsync(Exception error)
    {
        await DropAsync().ConfigureAwait(false);
        string reason = _certificateProblem is { } why ? "TLS: " + why : Describe(error);
        _certificateProblem = null;
        return (reason, Backoff());
    }

    /// <summary>
    /// Why a connection failed, in a few words: the socket's own (<c>Connection refused</c>) when there is one — the log
    /// names the broker already, and MQTTnet's wrapper would name it again as a DnsEndPoint
    /// (<c>Unspecified/127.0.0.1:1883</c>) — otherwise the messages of the exception and its causes, each once.
    /// </summary>
    public static string Describe(Exception error)
    {
        ArgumentNullException.ThrowIfNull(error);
        for (Exception? x = error; x is not null; x = x.InnerException)
        {
            if (x is System.Net.Sockets.SocketException socket)
            {
                return socket.Message;
            }
        }

        var parts = new List<string>();
        for (Exception? x = error; x is not null; x = x.InnerException)
        {
            string text = x.Message.TrimEnd('.');
            if (text.Length > 0 && !parts.Any(p => p.Contains(text, StringComparison.Ordinal)))
            {
                parts.Add(text);
            }
        }

        return parts.Count == 0 ? error.GetType().Name : string.Join(": ", parts).Replace("Unspecified/", "", StringComparison.Ordinal);
    }

    /// <summary>
    /// Counts a connection that ended (failed, lost, or closed by the output) and says how long to wait before the next
    /// attempt: Reconnect:Initial the first time since the last connection, doubling up to Reconnect:Max.
    /// </summary>
    public TimeSpan Backoff()
    {
        _backoff = FailedAttempts++ == 0 ? _options.Reconnect.Initial : TimeSpan.FromTicks(Math.Min(_backoff.Ticks * 2, _options.Reconnect.Max.Ticks));
        return _backoff;
    }

    /// <summary>Waits <paramref name="delay"/>; false when the loops are told to stop meanwhile.</summary>
    public async Task<bool> DelayAsync(TimeSpan delay)
    {
        try
        {
            await Task.Delay(delay, _time, _stop.Token).ConfigureAwait(false);
            return true;
        }
        catch (OperationCanceledException)
        {
            return false;
        }
    }

    /// <summary>
    /// Sends the output's last messages and disconnects, within <see cref="MqttBrokerOptions.Timeout"/>. If the broker
    /// goes away meanwhile, nothing is reported: it publishes the will instead.
    /// </summary>
    public async Task CloseAsync(Func<IMqttClient, CancellationToken, Task> lastMessages)
    {
        if (!Client.IsConnected)
        {
            return;
        }

        try
        {
            using var timeout = new CancellationTokenSource(_options.Timeout);
            await lastMessages(Client, timeout.Token).ConfigureAwait(false);
            await Client.DisconnectAsync(new MqttClientDisconnectOptions(), timeout.Token).ConfigureAwait(false);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // The broker went away meanwhile.
        }
    }

    /// <inheritdoc/>
    public async ValueTask DisposeAsync()
    {
        if (!_stop.IsCancellationRequested)
        {
            await _stop.CancelAsync().ConfigureAwait(false);
        }

        foreach (Task loop in _loops)
        {
            await loop.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        }

        Client.Dispose();
        _stop.Dispose();
    }

    private Task Run(Func<CancellationToken, Task> loop)
    {
        CancellationToken stop = _stop.Token;
        Task task = Task.Run(() => loop(stop), CancellationToken.None);
        _loops.Add(task);
        return task;
    }

    /// <summary>Closes a connection that is still open, waiting 2 s at most; a connection already gone is left alone.</summary>
    private async Task DropAsync()
    {
        if (!Client.IsConnected)
        {
            return;
        }

        try
        {
            using var timeout = new CancellationTokenSource(DropLimit);
            await Client.DisconnectAsync(new MqttClientDisconnectOptions(), timeout.Token).ConfigureAwait(false);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // Already gone.
        }
    }
}
