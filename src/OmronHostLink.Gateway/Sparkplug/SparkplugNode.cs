using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The edge node's view of the tags, fed by the polling (it is an <see cref="ITagOutput"/>): every metric's current
/// value, read time and quality, and which device is alive. A device is born (DBIRTH) once each of its tags has been
/// read (or answered with an error) since it was last dead, so that its birth carries every value; it dies (DDEATH) when
/// its unit stops answering or is demoted, or its link stops. Between, the metrics whose value or quality changed go out
/// by alias in DDATA, each with the time the PLC was read. The outputs' calls return at once: they only mark what
/// changed, and <see cref="Changed"/> wakes the publisher, which takes the messages (<see cref="TakeMessages"/>) and
/// numbers them in the order it publishes them.
/// </summary>
internal sealed class SparkplugNode : ITagOutput
{
    private readonly object _gate = new();
    private readonly Dictionary<(string Link, int Unit), DeviceState> _devices = new();
    private readonly Dictionary<string, DeviceState> _byId = new(StringComparer.Ordinal);
    private readonly SparkplugSequence _sequence = new();
    private readonly TimeProvider _time;
    private bool _rebirth;

    /// <summary>Creates the node for the catalogue's tags.</summary>
    public SparkplugNode(SparkplugOptions options, TagCatalog catalog, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(options);
        GroupId = options.GroupId;
        EdgeNodeId = options.EdgeNodeId;
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

    /// <summary>The device with id <paramref name="id"/>; null when this node has none.</summary>
    public SparkplugDevice? Device(string id) => _byId.TryGetValue(id, out DeviceState? state) ? state.Device : null;

    /// <summary>The node's topic of <paramref name="type"/>, for a device or the node itself.</summary>
    public SparkplugTopic Topic(SparkplugMessageType type, string? deviceId = null) => new(GroupId, type, EdgeNodeId, deviceId);

    /// <summary>
    /// The births of a new session (after a connection, or asked for with <c>Node Control/Rebirth</c>): NBIRTH with seq 0
    /// and <paramref name="bdSeq"/>, then a DBIRTH for every device whose unit answers. Pending data is in them.
    /// </summary>
    public List<SparkplugMessage> Births(ulong bdSeq)
    {
        lock (_gate)
        {
            _rebirth = false;
            _sequence.Reset();
            DateTimeOffset now = _time.GetUtcNow();
            var messages = new List<SparkplugMessage>
            {
                new(Topic(SparkplugMessageType.NBIRTH), SparkplugPayloads.NodeBirth(bdSeq, now)),
            };
            _sequence.Next();
            foreach (DeviceState device in _devices.Values)
            {
                device.Born = false;
                device.Dirty.Clear();
                if (device.Alive)
                {
                    messages.Add(Birth(device, now));
                }
            }

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
        }

        Changed?.Invoke();
    }

    /// <summary>
    /// The deaths, births and data since the last call, numbered in order. With <paramref name="connected"/> false
    /// nothing is numbered or returned (a host application learns the state from the next session's births).
    /// </summary>
    public List<SparkplugMessage> TakeMessages(bool connected)
    {
        lock (_gate)
        {
            var messages = new List<SparkplugMessage>();
            DateTimeOffset now = _time.GetUtcNow();
            foreach (DeviceState device in _devices.Values)
            {
                if (!connected)
                {
                    device.Dirty.Clear();
                    continue;
                }

                if (device.Born && !device.Alive)
                {
                    device.Born = false;
                    device.Dirty.Clear();
                    messages.Add(new(Topic(SparkplugMessageType.DDEATH, device.Device.Id), SparkplugPayloads.DeviceDeath(_sequence.Next(), now)));
                }
                else if (!device.Born && device.Alive)
                {
                    device.Dirty.Clear();
                    messages.Add(Birth(device, now));
                }
                else if (device.Born && device.Dirty.Count > 0)
                {
                    SparkplugMetricValue[] changed = device.Dirty.Order().Select(device.Value).ToArray();
                    device.Dirty.Clear();
                    messages.Add(new(Topic(SparkplugMessageType.DDATA, device.Device.Id), SparkplugPayloads.Data(_sequence.Next(), now, changed)));
                }
            }

            return messages;
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

            changed = device.Apply(change);
        }

        if (changed)
        {
            Changed?.Invoke();
        }
    }

    private SparkplugMessage Birth(DeviceState device, DateTimeOffset now)
    {
        device.Born = true;
        SparkplugMetricValue[] metrics = Enumerable.Range(0, device.Device.Metrics.Count).Select(device.Value).ToArray();
        return new(Topic(SparkplugMessageType.DBIRTH, device.Device.Id), SparkplugPayloads.DeviceBirth(_sequence.Next(), now, metrics));
    }

    /// <summary>A device's metrics as last read, whether it is alive, and whether a host application has its birth.</summary>
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

        /// <summary>Metrics (by index) changed since the last message.</summary>
        public HashSet<int> Dirty { get; } = new();

        /// <summary>The unit stopped answering: dead until every tag has been read again.</summary>
        public void Die()
        {
            Alive = false;
            _answered.Clear();
        }

        public SparkplugMetricValue Value(int index) => new(Device.Metrics[index], _values[index], _times[index], _qualities[index]);

        /// <summary>Takes a tag's outcome; true when it changes what a host application should know.</summary>
        public bool Apply(TagChange change)
        {
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

            int quality = change.Quality == TagQuality.Good ? SparkplugQuality.Good : SparkplugQuality.Stale;
            foreach (int index in metrics)
            {
                SparkplugMetric metric = Device.Metrics[index];
                object? value = _values[index];
                if (change.Quality == TagQuality.Good)
                {
                    value = metric.Element < 0 ? change.Value : ((Array)change.Value!).GetValue(metric.Element);
                }

                if (Equals(value, _values[index]) && quality == _qualities[index])
                {
                    continue;
                }

                _values[index] = value;
                _qualities[index] = quality;
                _times[index] = change.Time;
                Dirty.Add(index);
                changed = true;
            }

            return changed;
        }
    }
}
