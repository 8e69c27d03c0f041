using System.Security.Cryptography.X509Certificates;
using Microsoft.Extensions.Logging;
using MQTTnet;
using MQTTnet.Exceptions;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// What every MQTT output keeps of its broker connection (<see cref="MqttBrokerOptions"/>): the one client, the loops that
/// use it and their stop, the servers it may use and the one in use, the client options with the certificate checks,
/// the walk to the next server and the backoff between rounds, how each connection ended — a session taken over by
/// another client with the same id included — and a snapshot of it all (<see cref="Status"/>). There is one client, so
/// there is never more than one connection: the next server is tried only once the last connection is closed. The output
/// decides what is sent, when, and what it logs of a failure.
/// </summary>
/// <remarks>
/// Walking and backoff: a failed attempt or a lost connection moves to the next server of the list; the next server is
/// tried at once, and only after every server has failed in a row does the connection wait, Reconnect:Initial after the
/// first round, doubling up to Reconnect:Max. The count of failures starts again only once a connection has lasted
/// <see cref="StableAfter"/> (twice Reconnect:Max): a connection the broker ends sooner — a session taken over by
/// another gateway with the same client id is the usual cause — keeps the delay growing, so two such gateways take
/// turns once per Reconnect:Max instead of throwing each other out many times a second.
/// </remarks>
internal sealed class MqttBrokerConnection : IAsyncDisposable
{
    private static readonly TimeSpan DropLimit = TimeSpan.FromSeconds(2);

    /// <summary>How long to wait for the client's report of how a connection ended.</summary>
    private static readonly TimeSpan EndReportLimit = TimeSpan.FromSeconds(2);

    private readonly MqttBrokerOptions _options;
    private readonly string _output;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly CancellationTokenSource _stop = new();
    private readonly List<Task> _loops = [];
    private readonly object _gate = new();
    private readonly X509Certificate2?[] _certificates;
    private TaskCompletionSource<MqttClientDisconnectedEventArgs> _ended = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private volatile string? _certificateProblem;
    private volatile string? _abortReason;
    private int _server;
    private int _lastConnectedServer = -1;
    private int _failures;
    private long _connectedAt;
    private DateTimeOffset? _connectedSince;
    private DateTimeOffset? _lastPublished;
    private bool _closingOnPurpose;
    private bool _quickReconnectAfterBrokerClose;
    private bool _lastEndWasBrokerClose;
    private bool _duplicateEpisode;
    private BrokerState _state = BrokerState.Starting;
    private long _connections;
    private int _failedAttempts;
    private string? _lastProblem;
    private DateTimeOffset? _lastProblemAt;

    /// <summary>Makes the client; nothing connects until a loop does.</summary>
    /// <param name="options">The validated broker settings.</param>
    /// <param name="section">The section's key (<c>Mqtt</c>, <c>Sparkplug</c>).</param>
    /// <param name="output">The output's name as its logs start (<c>MQTT</c>, <c>Sparkplug</c>).</param>
    /// <param name="factory">Makes the client.</param>
    /// <param name="time">Times the waits between attempts and how long connections last.</param>
    /// <param name="logger">Where what every output says alike goes (the server in use, a duplicate client id).</param>
    public MqttBrokerConnection(MqttBrokerOptions options, string section, string output, MqttClientFactory factory, TimeProvider time, ILogger logger)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(factory);
        _options = options;
        Section = section;
        _output = output;
        _time = time;
        _logger = logger;
        Servers = options.ServersInEffect(section);
        _certificates = new X509Certificate2?[Servers.Count];
        Client = factory.CreateMqttClient();
        // Registered first, so that it has recorded how a connection ended before an output's handler wakes its loop.
        Client.DisconnectedAsync += e =>
        {
            _ended.TrySetResult(e);
            Changed?.Invoke();
            return Task.CompletedTask;
        };
    }

    /// <summary>The connection's state changed (connected, ended, another server).</summary>
    public event Action? Changed;

    /// <summary>The section's key (<c>Mqtt</c>, <c>Sparkplug</c>).</summary>
    public string Section { get; }

    /// <summary>The client.</summary>
    public IMqttClient Client { get; }

    /// <summary>The servers in order (one for the single-broker keys).</summary>
    public IReadOnlyList<MqttServer> Servers { get; }

    /// <summary>The server in use, or the one tried next.</summary>
    public MqttServer Server
    {
        get
        {
            lock (_gate)
            {
                return Servers[_server];
            }
        }
    }

    /// <summary>The server in use as the logs name it: <c>host:port</c>, with its key when there are several.</summary>
    public string Broker => Server.ToString();

    /// <summary>The client id in effect.</summary>
    public string ClientId => _options.ClientIdOrDefault;

    /// <summary>
    /// How long a connection must last to count as established: twice Reconnect:Max. A connection that ends sooner
    /// does not start the backoff over.
    /// </summary>
    public TimeSpan StableAfter => _options.Reconnect.Max * 2;

    /// <summary>
    /// How long a connection that died without a word can go unnoticed at most: 1.5 × KeepAlive, as the broker counts
    /// (with <see cref="LivenessAsync"/> running, a ping is due every KeepAlive and answered within half of it).
    /// </summary>
    public TimeSpan UnnoticedLossLimit => _options.KeepAlive * 1.5;

    /// <summary>The loop that connects and sends, once started.</summary>
    public Task? ConnectionLoop { get; private set; }

    /// <summary>Whether the loops are told to stop.</summary>
    public bool IsStopping => _stop.IsCancellationRequested;

    /// <summary>How many attempts have failed since the last connection (or since the start).</summary>
    public int FailedAttempts
    {
        get
        {
            lock (_gate)
            {
                return _failedAttempts;
            }
        }
    }

    /// <summary>What the output adds to <see cref="Status"/>; read on every snapshot.</summary>
    public Func<BrokerSession>? Session { get; set; }

    /// <summary>A snapshot of the connection, for the statistics and a status page.</summary>
    public BrokerStatus Status()
    {
        BrokerSession? session = Session?.Invoke();
        lock (_gate)
        {
            MqttServer server = Servers[_server];
            return new BrokerStatus(
                Section.ToLowerInvariant(),
                ClientId,
                // A connection the broker ended is no longer one, even before the output's loop has taken note.
                _state == BrokerState.Connected && !Client.IsConnected ? BrokerState.Waiting : _state,
                server.Address,
                server.Key,
                server.Index + 1,
                Servers.Select(s => s.Address).ToArray(),
                _connectedSince,
                _connections,
                _failedAttempts,
                _lastProblem,
                _lastProblemAt,
                _duplicateEpisode,
                session);
        }
    }

    /// <summary>Starts the client options for the server in use: credentials, TLS and its client certificate, a refused broker certificate remembered for <see cref="FailedAsync"/>.</summary>
    public MqttClientOptionsBuilder ClientOptions()
    {
        MqttServer server = Server;
        return MqttClientOptionsFactory.Create(_options, server, Certificate(server), why => _certificateProblem = why);
    }

    /// <summary>Starts the connection loop and the output's other loops, each given the token that stops them.</summary>
    /// <param name="connectionLoop">The loop that connects and sends (<see cref="ConnectionLoop"/>).</param>
    /// <param name="others">Loops that only end with the connection's (commands, <see cref="LivenessAsync"/>).</param>
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

    /// <summary>An attempt to connect to <see cref="Server"/> starts.</summary>
    public void Connecting()
    {
        lock (_gate)
        {
            _state = BrokerState.Connecting;
            _ended = new TaskCompletionSource<MqttClientDisconnectedEventArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
            _closingOnPurpose = false;
            _abortReason = null;
        }

        Changed?.Invoke();
    }

    /// <summary>When the broker last took a message of the output (<see cref="Published"/>); null before the first.</summary>
    public DateTimeOffset? LastPublished
    {
        get
        {
            lock (_gate)
            {
                return _lastPublished;
            }
        }
    }

    /// <summary>The broker took a message of the output.</summary>
    public void Published()
    {
        lock (_gate)
        {
            _lastPublished = _time.GetUtcNow();
        }
    }

    /// <summary>
    /// A connection to <see cref="Server"/> is up. Logs the server in use when it is another than the last one connected
    /// to (and, with a list, at the first connection).
    /// </summary>
    public void Connected()
    {
        bool changed;
        MqttServer server;
        lock (_gate)
        {
            server = Servers[_server];
            changed = _lastConnectedServer != _server;
            // A reconnection at the first attempt after the broker closed the last connection: if this one too is closed
            // soon, another client is probably taking the session over (MQTT 3.1.1 says no more).
            _quickReconnectAfterBrokerClose = _lastEndWasBrokerClose && _failedAttempts == 1 && !changed;
            _lastConnectedServer = _server;
            _connectedAt = _time.GetTimestamp();
            _ended = new TaskCompletionSource<MqttClientDisconnectedEventArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
            _connectedSince = _time.GetUtcNow();
            _failedAttempts = 0;
            _connections++;
            _state = BrokerState.Connected;
        }

        if (changed && Servers.Count > 1)
        {
            BrokerLog.ServerInUse(_logger, _output, server.ToString(), server.Index + 1, Servers.Count);
        }

        Changed?.Invoke();
    }

    /// <summary>
    /// After a failed attempt or a lost connection (<paramref name="error"/> null when the loop found the client
    /// disconnected): closes what is left, says why it failed — a refused certificate, a session taken over by another
    /// client with the same id, a ping not answered, otherwise <see cref="Describe"/>'s words — moves to the next server
    /// and says how long to wait. Logs a duplicate client id (once until a connection lasts <see cref="StableAfter"/>).
    /// </summary>
    public async Task<ConnectionEnd> FailedAsync(Exception? error)
    {
        bool wasConnected;
        lock (_gate)
        {
            wasConnected = _connectedAt != 0;
        }

        MqttClientDisconnectedEventArgs? report = null;
        if (wasConnected && !Client.IsConnected)
        {
            // How the connection ended, as the client saw it: a DISCONNECT with a reason, an error, or the socket closed.
            try
            {
                report = await _ended.Task.WaitAsync(EndReportLimit, _time).ConfigureAwait(false);
            }
            catch (TimeoutException)
            {
                // Not reported: the reason is the error's, or unknown.
            }
        }

        bool onPurpose;
        lock (_gate)
        {
            onPurpose = _closingOnPurpose;
        }

        await DropAsync().ConfigureAwait(false);
        bool takenOver = IsTakenOver(error, report);
        // MQTT 3.1.1 has no DISCONNECT from the broker, and Mosquitto 2.0 sends none to an MQTT 5 client either: a session
        // taken over ends with the socket closed, as one whose broker goes down does. (The reason MQTTnet reports is that
        // of the last DISCONNECT received, on any connection: not a sign.)
        bool brokerClosed = !takenOver && !onPurpose && _abortReason is null && error is null or MqttCommunicationException
            && report is { ClientWasConnected: true, Exception: null };
        string reason = _certificateProblem is { } why ? "TLS: " + why
            : _abortReason is { } aborted ? aborted
            : takenOver ? "another client connected with the same client id: session taken over"
            : !wasConnected && ClientCertificateRefused(error) is { } refused ? refused
            : error is not null ? Describe(error)
            : report?.Exception is { } reported ? Describe(reported)
            : report is { Reason: not MqttClientDisconnectReason.NormalDisconnection } r ? $"the broker disconnected the client: {r.Reason}{(string.IsNullOrEmpty(r.ReasonString) ? "" : " " + r.ReasonString)}"
            : wasConnected ? "the broker closed the connection" : "the connection failed";
        _certificateProblem = null;
        _abortReason = null;
        return End(reason, wasConnected, takenOver, brokerClosed);
    }

    /// <summary>
    /// Ends the connection on purpose (a Sparkplug primary host gone offline): sends the output's last messages,
    /// disconnects, and moves on as after a failure — to the next server of the list, or after the backoff to the same
    /// one.
    /// </summary>
    public async Task<ConnectionEnd> EndAsync(Func<IMqttClient, CancellationToken, Task> lastMessages, string reason)
    {
        bool wasConnected;
        lock (_gate)
        {
            wasConnected = _connectedAt != 0;
        }

        await CloseAsync(lastMessages).ConfigureAwait(false);
        return End(reason, wasConnected, takenOver: false, brokerClosed: false);
    }

    /// <summary>
    /// Takes the connection as lost (a ping unanswered, a message that could not be sent in time): drops it, and the next
    /// <see cref="FailedAsync"/> gives <paramref name="reason"/>.
    /// </summary>
    public async Task AbortAsync(string reason)
    {
        _abortReason = reason;
        await DropAsync().ConfigureAwait(false);
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

    /// <summary>Waits <paramref name="delay"/>; false when the loops are told to stop meanwhile.</summary>
    public async Task<bool> DelayAsync(TimeSpan delay)
    {
        if (delay <= TimeSpan.Zero)
        {
            return !_stop.IsCancellationRequested;
        }

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
    /// Pings the broker every KeepAlive while connected and takes the connection as lost when no answer comes within
    /// half of it. MQTTnet pings only a connection that sent nothing for a keep-alive period, and a stream of QoS 0
    /// messages into a connection that died without a word would otherwise go unnoticed until TCP gives up, minutes
    /// later; with this, a loss is noticed within <see cref="UnnoticedLossLimit"/>.
    /// </summary>
    public async Task LivenessAsync(CancellationToken cancellationToken)
    {
        TimeSpan period = _options.KeepAlive;
        TimeSpan answerWithin = period / 2;
        while (!cancellationToken.IsCancellationRequested)
        {
            try
            {
                await Task.Delay(period, _time, cancellationToken).ConfigureAwait(false);
                if (!Client.IsConnected)
                {
                    continue;
                }

                using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
                timeout.CancelAfter(answerWithin);
                await Client.PingAsync(timeout.Token).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
            {
                return;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                if (Client.IsConnected)
                {
                    BrokerLog.PingUnanswered(_logger, _output, Broker, answerWithin.TotalSeconds);
                    await AbortAsync($"no answer to a ping within {answerWithin.TotalSeconds:0.###} s").ConfigureAwait(false);
                }
            }
        }
    }

    /// <summary>
    /// Sends the output's last messages and disconnects, within <see cref="MqttBrokerOptions.Timeout"/>. If the broker
    /// goes away meanwhile, nothing is reported: it publishes the will instead.
    /// </summary>
    public async Task CloseAsync(Func<IMqttClient, CancellationToken, Task> lastMessages)
    {
        ArgumentNullException.ThrowIfNull(lastMessages);
        lock (_gate)
        {
            _closingOnPurpose = true;
        }

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

    /// <summary>The gateway stops: the connection is closed for good.</summary>
    public void Stopped()
    {
        lock (_gate)
        {
            _state = BrokerState.Stopped;
            _connectedAt = 0;
            _connectedSince = null;
        }

        Changed?.Invoke();
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
        foreach (X509Certificate2? certificate in _certificates)
        {
            certificate?.Dispose();
        }
    }

    private static bool IsTakenOver(Exception? error, MqttClientDisconnectedEventArgs? report)
    {
        for (Exception? x = error; x is not null; x = x.InnerException)
        {
            if (x is MqttClientUnexpectedDisconnectReceivedException { ReasonCode: MQTTnet.Protocol.MqttDisconnectReasonCode.SessionTakenOver })
            {
                return true;
            }
        }

        // A DISCONNECT received sets the reason MQTTnet reports, and nothing else resets it: an error (a socket reset)
        // means this connection ended otherwise.
        return report is { Exception: null, Reason: MqttClientDisconnectReason.SessionTakenOver } && error is null or MqttClientDisconnectedException;
    }

    /// <summary>
    /// The walk and the backoff after a failure or an end: the count of failures starts again after a lasting
    /// connection; the next server comes at once unless every server has just failed in a row, then the delay doubles
    /// each round. A duplicate client id is logged here, once an episode.
    /// </summary>
    private ConnectionEnd End(string reason, bool wasConnected, bool takenOver, bool brokerClosed)
    {
        MqttServer failed;
        MqttServer next;
        TimeSpan delay;
        bool first;
        string? evidence = null;
        bool again = false;
        bool duplicate;
        lock (_gate)
        {
            failed = Servers[_server];
            TimeSpan lasted = wasConnected ? _time.GetElapsedTime(_connectedAt) : TimeSpan.Zero;
            bool lasting = wasConnected && lasted >= StableAfter;
            if (lasting)
            {
                _failures = 0;
                _duplicateEpisode = false;
            }

            if (takenOver)
            {
                evidence = "the broker said the session was taken over";
            }
            else if (brokerClosed && !lasting && _quickReconnectAfterBrokerClose)
            {
                evidence = $"it closed the connection {lasted.TotalSeconds:0.#} s after accepting it, the second time in a row, and accepted the next one at once";
            }

            if (evidence is not null)
            {
                again = _duplicateEpisode;
                _duplicateEpisode = true;
            }

            duplicate = _duplicateEpisode;
            _lastEndWasBrokerClose = brokerClosed && !lasting;
            _quickReconnectAfterBrokerClose = false;
            _failures++;
            _failedAttempts++;
            first = _failedAttempts == 1;
            _server = (_server + 1) % Servers.Count;
            next = Servers[_server];
            delay = Servers.Count > 1 && _failures % Servers.Count != 0 ? TimeSpan.Zero : BackoffStep(_failures / Servers.Count);
            _connectedAt = 0;
            _connectedSince = null;
            _state = BrokerState.Waiting;
            _lastProblem = reason;
            _lastProblemAt = _time.GetUtcNow();
        }

        if (evidence is not null)
        {
            if (again)
            {
                BrokerLog.DuplicateIdentityAgain(_logger, _output, failed.ToString(), ClientId, delay.TotalSeconds);
            }
            else
            {
                BrokerLog.DuplicateIdentity(_logger, _output, failed.ToString(), ClientId, evidence, Section + ":ClientId", delay.TotalSeconds, _options.Reconnect.Max.TotalSeconds, StableAfter.TotalSeconds);
            }
        }

        Changed?.Invoke();
        return new ConnectionEnd(failed, reason, delay, next, wasConnected, first, duplicate);
    }

    /// <summary>Reconnect:Initial for the first round of failures, doubling each round up to Reconnect:Max.</summary>
    private TimeSpan BackoffStep(int round)
    {
        TimeSpan delay = _options.Reconnect.Initial;
        for (int i = 1; i < round && delay < _options.Reconnect.Max; i++)
        {
            delay *= 2;
        }

        return delay < _options.Reconnect.Max ? delay : _options.Reconnect.Max;
    }

    /// <summary>
    /// The broker refused this gateway's client certificate: the words say so and name the key of the certificate. Under
    /// TLS 1.2 the refusal is an alert during the handshake; under TLS 1.3 the client's handshake is over before the
    /// broker has checked the certificate, and the broker then closes the connection before answering CONNECT — which a
    /// broker that took the certificate does not do. Null when the failure is neither.
    /// </summary>
    private string? ClientCertificateRefused(Exception? error)
    {
        MqttServer server = Server;
        if (error is null || string.IsNullOrEmpty(server.Tls.ClientCertificateFile) || Certificate(server) is not { } certificate)
        {
            return null;
        }

        string text = Describe(error);
        string key = MqttClientOptionsFactory.TlsKey(_options, server) + ":ClientCertificateFile";
        string[] alerts = ["alert unknown ca", "alert bad certificate", "alert certificate", "alert unsupported certificate", "alert access denied", "alert decrypt error", "UnknownCA", "BadCertificate", "CertificateRequired", "CertificateExpired", "CertificateRevoked", "CertificateUnknown", "AccessDenied"];
        if (alerts.Any(a => text.Contains(a, StringComparison.OrdinalIgnoreCase)))
        {
            return $"the broker refused the client certificate of {key} ({ClientCertificate.Describe(certificate)}): {text}";
        }

        bool closedAfterHandshake = false;
        for (Exception? x = error; x is not null; x = x.InnerException)
        {
            if (x is System.Security.Authentication.AuthenticationException)
            {
                // The handshake itself failed, for another reason (the broker's certificate, a protocol): said as it is.
                return null;
            }

            closedAfterHandshake |= x is System.Net.Sockets.SocketException { SocketErrorCode: System.Net.Sockets.SocketError.NotConnected or System.Net.Sockets.SocketError.ConnectionReset or System.Net.Sockets.SocketError.ConnectionAborted or System.Net.Sockets.SocketError.Shutdown }
                || x is EndOfStreamException
                || (x is MqttCommunicationException && x.Message.Contains("closed", StringComparison.OrdinalIgnoreCase))
                || (x is IOException && x.Message.Contains("EOF", StringComparison.OrdinalIgnoreCase));
        }

        return closedAfterHandshake
            ? $"the broker refused the client certificate of {key} ({ClientCertificate.Describe(certificate)}): it closed the connection after the TLS handshake without answering CONNECT ({text})"
            : null;
    }

    private X509Certificate2? Certificate(MqttServer server)
    {
        if (!server.Tls.Enabled || string.IsNullOrEmpty(server.Tls.ClientCertificateFile))
        {
            return null;
        }

        lock (_gate)
        {
            // Checked at start (the section's validator); read once.
            return _certificates[server.Index] ??= ClientCertificate.Load(server.Tls, MqttClientOptionsFactory.TlsKey(_options, server), _time.GetUtcNow());
        }
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

        lock (_gate)
        {
            _closingOnPurpose = true;
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
