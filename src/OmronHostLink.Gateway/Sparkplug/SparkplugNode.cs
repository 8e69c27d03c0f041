using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Sparkplug.Wire;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The edge node's view of the tags, fed by the polling (it is an <see cref="ITagOutput"/>): every metric's current
/// value, read time and quality, which device is alive, and every change not yet published. A device is born (DBIRTH)
/// once each of its tags has been read (or answered with an error) since it was last dead, so that its birth carries
/// every value; it dies (DDEATH) when its unit stops answering or is demoted, or its link stops. In a session each change
/// of a born device goes out by alias in DDATA, in the order it was read, with the time the PLC was read; outside a
/// session (no broker, the primary host offline, a device not born yet) it is kept by store-and-forward
/// (<see cref="SparkplugHistory"/>) and published after the next births as history (<see cref="TakeHistory"/>). The
/// outputs' calls return at once: they only record what changed, and <see cref="Changed"/> wakes the publisher, which
/// takes the messages (<see cref="TakeMessages"/>) and numbers them in the order it publishes them.
/// </summary>
internal sealed class SparkplugNode : ITagOutput
{
    /// <summary>The most stored changes one historical DDATA carries.</summary>
    public const int HistoryBatch = 100;

    private readonly object _gate = new();
    private readonly Dictionary<(string Link, int Unit), DeviceState> _devices = new();
    private readonly Dictionary<string, DeviceState> _byId = new(StringComparer.Ordinal);
    private readonly SparkplugSequence _sequence = new();
    private readonly SparkplugHistory _history;
    private readonly TimeProvider _time;
    private bool _rebirth;
    private bool _session;
    private bool _historyBlocked;
    private long _droppedAnnounced;
    private long _births;
    private long _rebirthsRequested;

    /// <summary>Creates the node for the catalogue's tags, keeping changes outside a session in <paramref name="history"/>.</summary>
    public SparkplugNode(SparkplugOptions options, TagCatalog catalog, SparkplugHistory history, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(history);
        GroupId = options.GroupId;
        EdgeNodeId = options.EdgeNodeId;
        _history = history;
        _time = time;
        foreach (SparkplugDevice device in SparkplugDevice.FromCatalog(catalog))
        {
            var state = new DeviceState(device, time.GetUtcNow());
            _devices[(device.Link, device.Unit)] = state;
            _byId[device.Id] = state;
        }
    }

    /// <summary>Something changed that is worth publishing (or a rebirth was asked for).</summary>
    public event Action? Changed;

    /// <summary>The group id.</summary>
    public string GroupId { get; }

    /// <summary>The edge node id.</summary>
    public string EdgeNodeId { get; }

    /// <summary>The devices, in alias order.</summary>
    public IEnumerable<SparkplugDevice> Devices => _devices.Values.Select(d => d.Device);

    /// <summary>Births published (NBIRTH and DBIRTH) since the gateway started.</summary>
    public long BirthsPublished
    {
        get
        {
            lock (_gate)
            {
                return _births;
            }
        }
    }

    /// <summary>Rebirths host applications asked for (NCMD <c>Node Control/Rebirth</c>) since the gateway started.</summary>
    public long RebirthsRequested
    {
        get
        {
            lock (_gate)
            {
                return _rebirthsRequested;
            }
        }
    }

    /// <summary>What store-and-forward holds and has done: kept now, published as history, dropped.</summary>
    public (int Stored, long Sent, long Dropped) Store
    {
        get
        {
            lock (_gate)
            {
                return (_history.Count, _history.Sent, _history.Dropped);
            }
        }
    }

    /// <summary>The device with id <paramref name="id"/>; null when this node has none.</summary>
    public SparkplugDevice? Device(string id) => _byId.TryGetValue(id, out DeviceState? state) ? state.Device : null;

    /// <summary>The node's topic of <paramref name="type"/>, for a device or the node itself.</summary>
    public SparkplugTopic Topic(SparkplugMessageType type, string? deviceId = null) => new(GroupId, type, EdgeNodeId, deviceId);

    /// <summary>
    /// The births of a new session (after a connection, or asked for with <c>Node Control/Rebirth</c>): NBIRTH with seq 0,
    /// <paramref name="bdSeq"/> and the store's drop count, then a DBIRTH for every device whose unit answers. Changes not
    /// yet published are kept as history: the births carry the current values, and the history what came before.
    /// </summary>
    public List<SparkplugMessage> Births(ulong bdSeq)
    {
        lock (_gate)
        {
            _rebirth = false;
            _session = true;
            _historyBlocked = false;
            _sequence.Reset();
            DateTimeOffset now = _time.GetUtcNow();
            _droppedAnnounced = _history.Dropped;
            var messages = new List<SparkplugMessage>
            {
                new(Topic(SparkplugMessageType.NBIRTH), SparkplugPayloads.NodeBirth(bdSeq, now, NodeMetrics())),
            };
            _sequence.Next();
            foreach (DeviceState device in _devices.Values)
            {
                KeepPending(device);
                device.Born = false;
                if (device.Alive)
                {
                    messages.Add(Birth(device, now));
                }
            }

            _births += messages.Count;
            _history.Announced();
            return messages;
        }
    }

    /// <summary>Whether a host application asked for new births and they have not been sent yet.</summary>
    public bool RebirthRequested
    {
        get
        {
            lock (_gate)
            {
                return _rebirth;
            }
        }
    }

    /// <summary>Marks that a host application asked for new births (NCMD <c>Node Control/Rebirth</c>).</summary>
    public void RequestRebirth()
    {
        lock (_gate)
        {
            _rebirth = true;
            _rebirthsRequested++;
        }

        Changed?.Invoke();
    }

    /// <summary>
    /// The session ended: changes from now on are kept. <paramref name="lost"/> for a connection that died (the changes
    /// published in the window before it was noticed are kept again, as those not published yet); false for a session
    /// ended on purpose (the primary host offline, the gateway stopping).
    /// </summary>
    public void SessionEnded(bool lost)
    {
        lock (_gate)
        {
            if (lost)
            {
                _history.ConnectionLost();
            }
            else
            {
                _history.SessionEnded();
            }

            _session = false;
            foreach (DeviceState device in _devices.Values)
            {
                KeepPending(device);
                device.Born = false;
            }
        }
    }

    /// <summary>
    /// The deaths, births and data since the last call, numbered in order: in a session, the live messages. A device that
    /// died gets its pending data, then its DDEATH; one that came back, its DBIRTH; one with changes, a DDATA of them in
    /// the order they were read (a metric changed twice is in it twice, each with its own time). A grown drop count of
    /// store-and-forward goes out as NDATA.
    /// </summary>
    public List<SparkplugMessage> TakeMessages()
    {
        lock (_gate)
        {
            var messages = new List<SparkplugMessage>();
            if (!_session)
            {
                return messages;
            }

            DateTimeOffset now = _time.GetUtcNow();
            if (_history.Dropped != _droppedAnnounced)
            {
                _droppedAnnounced = _history.Dropped;
                messages.Add(new(Topic(SparkplugMessageType.NDATA), SparkplugPayloads.NodeData(_sequence.Next(), now, NodeMetrics())));
            }

            foreach (DeviceState device in _devices.Values)
            {
                if (device.Born && device.Pending.Count > 0)
                {
                    AddData(messages, device, now);
                }

                if (device.Born && !device.Alive)
                {
                    device.Born = false;
                    messages.Add(new(Topic(SparkplugMessageType.DDEATH, device.Device.Id), SparkplugPayloads.DeviceDeath(_sequence.Next(), now)));
                }
                else if (!device.Born && device.Alive)
                {
                    messages.Add(Birth(device, now));
                    _births++;
                    _historyBlocked = false;
                }
            }

            return messages;
        }
    }

    /// <summary>
    /// The next stored changes as one historical DDATA (<c>is_historical</c>, by alias, each with the time it was read),
    /// oldest first; null when none can go now (none kept, their device not born, or waiting for confirmation). Changes
    /// the births carry already (same metric, same time) are skipped; changes of a metric no longer configured are
    /// dropped and counted.
    /// </summary>
    public SparkplugMessage? TakeHistory()
    {
        lock (_gate)
        {
            if (!_session || _historyBlocked)
            {
                return null;
            }

            int postponed = 0;
            while (_history.Next(HistoryBatch) is { } batch)
            {
                if (!_byId.TryGetValue(batch.Device, out DeviceState? device) || !device.Born)
                {
                    if (device is not null && batch.AtHead && postponed < _history.Count)
                    {
                        // Its unit does not answer now: the changes of the other devices go first.
                        postponed += batch.Messages.Count;
                        _history.Postpone(batch);
                        continue;
                    }

                    if (device is null)
                    {
                        _history.Discarded(batch.Messages.Count);
                        _history.Skip(batch);
                        continue;
                    }

                    // Nothing else can go until its device is born, or what waits before it is confirmed.
                    _historyBlocked = batch.AtHead;
                    return null;
                }

                var metrics = new List<Payload.Types.Metric>();
                int discarded = 0;
                foreach (Payload.Types.Metric? change in batch.Changes)
                {
                    SparkplugMetric? metric = change is null ? null : device.Device.Metric(change.Name);
                    if (change is null || metric is null || change.Datatype != (uint)metric.DataType)
                    {
                        discarded++;
                        continue;
                    }

                    if (device.BirthTimes.TryGetValue(metric.Alias, out ulong born) && born == change.Timestamp)
                    {
                        // The birth of this session carries this value already.
                        continue;
                    }

                    Payload.Types.Metric historical = change.Clone();
                    historical.ClearName();
                    historical.Alias = metric.Alias;
                    historical.IsHistorical = true;
                    metrics.Add(historical);
                }

                _history.Discarded(discarded);
                if (metrics.Count == 0)
                {
                    _history.Skip(batch);
                    continue;
                }

                _history.MarkSent(batch, metrics.Count);
                return new SparkplugMessage(
                    Topic(SparkplugMessageType.DDATA, device.Device.Id),
                    SparkplugPayloads.HistoricalData(_sequence.Next(), _time.GetUtcNow(), metrics));
            }

            return null;
        }
    }

    /// <summary>When stored changes published as history are next due to be confirmed; null when none wait.</summary>
    public DateTimeOffset? NextConfirmation
    {
        get
        {
            lock (_gate)
            {
                return _history.NextConfirmation;
            }
        }
    }

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client)
    {
    }

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
        if (state != LinkState.Offline)
        {
            return;
        }

        bool changed = false;
        lock (_gate)
        {
            foreach (DeviceState device in _devices.Values.Where(d => d.Device.Link == link))
            {
                changed |= device.Alive;
                device.Die();
            }
        }

        if (changed)
        {
            Changed?.Invoke();
        }
    }

    /// <inheritdoc/>
    public void UnitChanged(string link, int unit, UnitState state, string? detail = null)
    {
        lock (_gate)
        {
            if (!_devices.TryGetValue((link, unit), out DeviceState? device))
            {
                return;
            }

            // Back online: born again once every tag has been read again. Out: dead now.
            if (state == UnitState.Online || !device.Alive)
            {
                return;
            }

            device.Die();
        }

        Changed?.Invoke();
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
        ArgumentNullException.ThrowIfNull(change);
        bool changed;
        lock (_gate)
        {
            if (!_devices.TryGetValue((change.Link, change.Unit), out DeviceState? device))
            {
                return;
            }

            changed = device.Apply(change, out List<SparkplugMetricValue>? values);
            foreach (SparkplugMetricValue value in values ?? [])
            {
                if (_session && device.Born)
                {
                    device.Pending.Add(value);
                }
                else
                {
                    _history.Store(device.Device.Id, value);
                }
            }
        }

        if (changed)
        {
            Changed?.Invoke();
        }
    }

    private IEnumerable<(string Name, long Value)> NodeMetrics()
        => _history.Enabled ? [(SparkplugPayloads.Dropped, _history.Dropped)] : [];

    /// <summary>Changes of a device not published live are kept as history.</summary>
    private void KeepPending(DeviceState device)
    {
        foreach (SparkplugMetricValue value in device.Pending)
        {
            _history.Store(device.Device.Id, value);
        }

        device.Pending.Clear();
    }

    /// <summary>
    /// A DDATA of the device's pending changes, in the order they were read; a metric that changed twice at the same
    /// millisecond starts another message (one message holds a metric twice only with different timestamps).
    /// </summary>
    private void AddData(List<SparkplugMessage> messages, DeviceState device, DateTimeOffset now)
    {
        var data = new List<SparkplugMetricValue>();
        var seen = new HashSet<(ulong, ulong)>();
        foreach (SparkplugMetricValue value in device.Pending)
        {
            if (!seen.Add((value.Metric.Alias, SparkplugValues.Timestamp(value.Time))))
            {
                messages.Add(new(Topic(SparkplugMessageType.DDATA, device.Device.Id), SparkplugPayloads.Data(_sequence.Next(), now, data)));
                data = [];
                seen.Clear();
                seen.Add((value.Metric.Alias, SparkplugValues.Timestamp(value.Time)));
            }

            data.Add(value);
        }

        messages.Add(new(Topic(SparkplugMessageType.DDATA, device.Device.Id), SparkplugPayloads.Data(_sequence.Next(), now, data)));
        _history.Published(device.Device.Id, device.Pending);
        device.Pending.Clear();
    }

    private SparkplugMessage Birth(DeviceState device, DateTimeOffset now)
    {
        device.Born = true;
        device.Pending.Clear();
        SparkplugMetricValue[] metrics = Enumerable.Range(0, device.Device.Metrics.Count).Select(device.Value).ToArray();
        device.BirthTimes.Clear();
        foreach (SparkplugMetricValue metric in metrics)
        {
            device.BirthTimes[metric.Metric.Alias] = SparkplugValues.Timestamp(metric.Time);
        }

        return new(Topic(SparkplugMessageType.DBIRTH, device.Device.Id), SparkplugPayloads.DeviceBirth(_sequence.Next(), now, metrics));
    }

    /// <summary>A device's metrics as last read, whether it is alive, whether a host application has its birth, and its changes not yet published.</summary>
    private sealed class DeviceState
    {
        private readonly object?[] _values;
        private readonly DateTimeOffset[] _times;
        private readonly int[] _qualities;
        private readonly Dictionary<string, int[]> _metricsOfTag = new(StringComparer.Ordinal);
        private readonly HashSet<string> _answered = new(StringComparer.Ordinal);

        public DeviceState(SparkplugDevice device, DateTimeOffset start)
        {
            Device = device;
            int n = device.Metrics.Count;
            _values = new object?[n];
            _times = Enumerable.Repeat(start, n).ToArray();
            _qualities = Enumerable.Repeat(SparkplugQuality.Bad, n).ToArray();
            for (int i = 0; i < n; i++)
            {
                SparkplugMetric metric = device.Metrics[i];
                _metricsOfTag[metric.Tag] = [.. _metricsOfTag.GetValueOrDefault(metric.Tag, []), i];
            }
        }

        public SparkplugDevice Device { get; }

        /// <summary>The unit answers: every tag has been read (or answered with an error) since the device was last dead.</summary>
        public bool Alive { get; private set; }

        /// <summary>The current session has its birth (and no death since).</summary>
        public bool Born { get; set; }

        /// <summary>Changes not published yet, in the order they were read.</summary>
        public List<SparkplugMetricValue> Pending { get; } = [];

        /// <summary>The read time of each metric (by alias) as the session's birth carried it.</summary>
        public Dictionary<ulong, ulong> BirthTimes { get; } = [];

        /// <summary>The unit stopped answering: dead until every tag has been read again.</summary>
        public void Die()
        {
            Alive = false;
            _answered.Clear();
        }

        public SparkplugMetricValue Value(int index) => new(Device.Metrics[index], _values[index], _times[index], _qualities[index]);

        /// <summary>
        /// Takes a tag's outcome; true when it changes what a host application should know. <paramref name="changes"/>
        /// gets the metrics whose value or quality changed, as they are now.
        /// </summary>
        public bool Apply(TagChange change, out List<SparkplugMetricValue>? changes)
        {
            changes = null;
            if (!_metricsOfTag.TryGetValue(change.Tag, out int[]? metrics))
            {
                return false;
            }

            if (change.Quality == TagQuality.CommError)
            {
                // The unit does not answer: that is the device's death, not a quality of its metrics (a DDATA of bad
                // qualities would otherwise go out just before the DDEATH). Its next birth carries what it reads then.
                bool wasAlive = Alive;
                Die();
                return wasAlive;
            }

            bool changed = false;
            if (!Alive && _answered.Add(change.Tag) && _answered.Count == _metricsOfTag.Count)
            {
                // The unit answered for every tag: alive, born at the next publication.
                Alive = true;
                changed = true;
            }

            foreach (int index in metrics)
            {
                SparkplugMetric metric = Device.Metrics[index];
                object? value = _values[index];
                if (change.Quality == TagQuality.Good)
                {
                    value = metric.Element < 0 ? change.Value : ((Array)change.Value!).GetValue(metric.Element);
                }

                // Specification 3.0, 6.4.x "Quality Codes": 192 good (not sent), 500 stale for a value that could not
                // be read again, 0 bad where there is no value at all.
                int quality = change.Quality == TagQuality.Good ? SparkplugQuality.Good : value is null ? SparkplugQuality.Bad : SparkplugQuality.Stale;
                if (Equals(value, _values[index]) && quality == _qualities[index])
                {
                    continue;
                }

                _values[index] = value;
                _qualities[index] = quality;
                _times[index] = change.Time;
                (changes ??= []).Add(Value(index));
                changed = true;
            }

            return changed;
        }
    }
}
