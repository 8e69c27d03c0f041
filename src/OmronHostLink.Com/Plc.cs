using System.Globalization;
using System.Runtime.InteropServices;
using OmronHostLink.Planning;

[assembly: Guid(OmronHostLink.Com.TypeLibrary.Id)]
[assembly: TypeLibVersion(1, 0)]

namespace OmronHostLink.Com;

/// <summary>
/// <c>OmronHostLink.Plc</c>: an Omron PLC over Host Link for VB6, VBA and VBScript, the way they used Omron's OCX. Each
/// call blocks until the PLC has answered (the library's deadlines: the line's speed plus the turnaround allowance,
/// reads retried), and a failure is raised as a COM error whose <c>Err.Number</c> is one of <see cref="PlcErrors"/> and
/// whose <c>Err.Description</c> is the library's message. A watch raises <see cref="IPlcEvents"/> on the thread that
/// called <see cref="Watch"/> and keeps each tag's latest value for callers without events.
/// </summary>
[ComVisible(true)]
[Guid("269D5FC2-B1DB-4DD3-9FF2-AD7640E49483")]
[ProgId(ProgId)]
[ClassInterface(ClassInterfaceType.None)]
[ComSourceInterfaces(typeof(IPlcEvents))]
public sealed class Plc : IPlc, IDisposable
{
    /// <summary>The ProgId scripts create it by: <c>CreateObject("OmronHostLink.Plc")</c>.</summary>
    public const string ProgId = "OmronHostLink.Plc";

    private readonly object _gate = new();
    private string _portName = "";
    private int _baudRate = 9600;
    private int _dataBits = 7;
    private string _parity = "E";
    private int _stopBits = 2;
    private string _host = "";
    private int _tcpPort;
    private int _unitNumber;
    private string _commandSet = nameof(HostLinkCommandSet.CMode);
    private int _turnaroundAllowance = (int)new HostLinkClientOptions().TurnaroundAllowance.TotalMilliseconds;
    private int _readRetries = new HostLinkClientOptions().ReadRetries;
    private HostLinkClient? _client;
    private IHostLinkUnit? _unit;
    private int _unitOfView;
    private PlcWatch? _watch;

    /// <summary>A watched tag's value changed.</summary>
    public event ValueChangedHandler? ValueChanged;

    /// <summary>The watch cannot read.</summary>
    public event ConnectionLostHandler? ConnectionLost;

    /// <summary>The watch reads again.</summary>
    public event ConnectionRestoredHandler? ConnectionRestored;

    /// <inheritdoc />
    public string PortName { get => _portName; set => SetForNextOpen(ref _portName, value ?? ""); }

    /// <inheritdoc />
    public int BaudRate { get => _baudRate; set => SetForNextOpen(ref _baudRate, value); }

    /// <inheritdoc />
    public int DataBits { get => _dataBits; set => SetForNextOpen(ref _dataBits, value); }

    /// <inheritdoc />
    public string Parity { get => _parity; set => SetForNextOpen(ref _parity, value ?? ""); }

    /// <inheritdoc />
    public int StopBits { get => _stopBits; set => SetForNextOpen(ref _stopBits, value); }

    /// <inheritdoc />
    public string Host { get => _host; set => SetForNextOpen(ref _host, value ?? ""); }

    /// <inheritdoc />
    public int TcpPort { get => _tcpPort; set => SetForNextOpen(ref _tcpPort, value); }

    /// <inheritdoc />
    /// <remarks>Checked by the next call that reaches the PLC (setters never throw; see <see cref="SetForNextOpen{T}"/>).</remarks>
    public int UnitNumber { get => _unitNumber; set => _unitNumber = value; }

    /// <inheritdoc />
    public string CommandSet { get => _commandSet; set => SetForNextOpen(ref _commandSet, value ?? ""); }

    /// <inheritdoc />
    public int TurnaroundAllowance { get => _turnaroundAllowance; set => SetForNextOpen(ref _turnaroundAllowance, value); }

    /// <inheritdoc />
    public int ReadRetries { get => _readRetries; set => SetForNextOpen(ref _readRetries, value); }

    /// <inheritdoc />
    public bool IsOpen => _client is not null;

    /// <inheritdoc />
    public string Description => _client?.Description ?? "";

    /// <inheritdoc />
    public bool IsWatching => _watch is { IsRunning: true };

    /// <inheritdoc />
    public string WatchError => _watch?.Error ?? "";

    /// <inheritdoc />
    public void Open(string connection = "")
    {
        lock (_gate)
        {
            if (_client is not null)
            {
                throw PlcErrors.Raise(PlcErrors.NotOpen, $"The link is already open ({_client.Description}); call Close first.");
            }

            HostLinkClientSettings settings;
            string what;
            try
            {
                (settings, what) = string.IsNullOrWhiteSpace(connection)
                    ? (FromProperties(), "The properties")
                    : (ConnectionString.Parse(connection), $"The connection string '{connection}'");
            }
            catch (FormatException e)
            {
                throw PlcErrors.Raise(PlcErrors.InvalidArgument, e.Message);
            }

            if (ConnectionString.Problems(settings, what) is { } problems)
            {
                throw PlcErrors.Raise(PlcErrors.InvalidArgument, problems);
            }

            HostLinkClient client;
            try
            {
                client = settings.CreateClient(o => o.LinkName = ProgId);
            }
            catch (Exception e)
            {
                throw PlcErrors.ToComError(e);
            }

            TakeProperties(settings);
            _client = client;
            _unit = client;
            _unitOfView = _unitNumber;
        }
    }

    /// <inheritdoc />
    public void Close()
    {
        HostLinkClient? client;
        lock (_gate)
        {
            client = _client;
            _client = null;
            _unit = null;
        }

        StopWatch();
        client?.Dispose();
    }

    /// <summary>The same as <see cref="Close"/>.</summary>
    public void Dispose() => Close();

    /// <inheritdoc />
    public int ReadWord(string address) => Call(u => (int)u.ReadWord(address));

    /// <inheritdoc />
    public object ReadWords(string address, int count) => Call(u => ComValues.Array(u.ReadWords(address, count), w => (object)(int)w));

    /// <inheritdoc />
    public void WriteWord(string address, int value) => Call(u => u.WriteWord(address, ComValues.Word(value, nameof(value))));

    /// <inheritdoc />
    public void WriteWords(string address, object values) => Call(u =>
    {
        object[] items = ComValues.Elements(values, nameof(values));
        var words = new ushort[items.Length];
        for (int i = 0; i < items.Length; i++)
        {
            words[i] = ComValues.Word(ComValues.WholeNumber(items[i], $"values({i})"), $"values({i})");
        }

        u.WriteWords(address, words);
    });

    /// <inheritdoc />
    public bool ReadBit(string address) => Call(u => u.ReadBit(address));

    /// <inheritdoc />
    public void WriteBit(string address, bool value) => Call(u => u.WriteBit(address, value));

    /// <inheritdoc />
    public int ReadBcd(string address) => Call(u => u.ReadBcd(address));

    /// <inheritdoc />
    public void WriteBcd(string address, int value) => Call(u => u.WriteBcd(address, value));

    /// <inheritdoc />
    public float ReadReal(string address) => Call(u => u.Read<float>(address));

    /// <inheritdoc />
    public void WriteReal(string address, float value) => Call(u => u.Write(address, value));

    /// <inheritdoc />
    public double ReadLReal(string address) => Call(u => u.Read<double>(address));

    /// <inheritdoc />
    public void WriteLReal(string address, double value) => Call(u => u.Write(address, value));

    /// <inheritdoc />
    public int ReadDint(string address) => Call(u => u.Read<int>(address));

    /// <inheritdoc />
    public void WriteDint(string address, int value) => Call(u => u.Write(address, value));

    /// <inheritdoc />
    public string ReadString(string address, int length) => Call(u => u.ReadString(address, length));

    /// <inheritdoc />
    public void WriteString(string address, string text) => Call(u => u.WriteString(address, text));

    /// <inheritdoc />
    public object Read(string tag) => Call(u => ComValues.From(u.ReadTags(tag)[0].Value));

    /// <inheritdoc />
    public void Write(string tag, object value) => Call(u => ComValues.Write(u, PlcTag.Parse(tag), value));

    /// <inheritdoc />
    public object ReadTags(object tags)
        => Call(u => ComValues.Array(u.ReadTags(ComValues.Tags(tags, nameof(tags))), v => ComValues.From(v.Value)));

    /// <inheritdoc />
    public IPlcStatus ReadStatus() => Call(u => new PlcStatusInfo(u.ReadStatus()));

    /// <inheritdoc />
    public string ReadMode() => Call(u => ComValues.ModeName(u.ReadStatus().Mode));

    /// <inheritdoc />
    public void SetMode(string mode) => Call(u => u.SetMode(ComValues.Mode(mode)));

    /// <inheritdoc />
    public string ReadErrors(bool clear = false) => Call(u => u.ReadErrors(clear).ToString());

    /// <inheritdoc />
    public string ReadModel() => Call(u => u.ReadModel().ToString());

    /// <inheritdoc />
    public double Test() => Call(u => u.Test().TotalMilliseconds);

    /// <inheritdoc />
    public void Watch(object tags, int intervalMilliseconds)
    {
        IHostLinkUnit unit = OpenUnit();
        PlcWatch watch;
        try
        {
            string[] texts = ComValues.Tags(tags, nameof(tags));
            if (intervalMilliseconds < 0)
            {
                throw new ArgumentOutOfRangeException(nameof(intervalMilliseconds), intervalMilliseconds, "The interval cannot be negative.");
            }

            watch = new PlcWatch(unit, texts, TimeSpan.FromMilliseconds(intervalMilliseconds), this);
        }
        catch (Exception e) when (e is not COMException)
        {
            throw PlcErrors.ToComError(e);
        }

        StopWatch();
        _watch = watch;
        watch.Start();
    }

    /// <inheritdoc />
    public void StopWatch()
    {
        PlcWatch? watch = _watch;
        _watch = null;
        watch?.Stop();
    }

    /// <inheritdoc />
    public object WatchedValue(string tag) => WatchOrRaise().LatestValue(tag);

    /// <inheritdoc />
    public object WaitForChanges(int timeoutMilliseconds)
    {
        if (timeoutMilliseconds < 0)
        {
            throw PlcErrors.Raise(PlcErrors.InvalidArgument, $"The timeout {timeoutMilliseconds} ms cannot be negative.");
        }

        return WatchOrRaise().WaitForChanges(TimeSpan.FromMilliseconds(timeoutMilliseconds));
    }

    /// <summary>Called by regsvr32 (through the comhost) after it registered the class: registers the type library.</summary>
    [ComRegisterFunction]
    private static void RegisterTypeLibrary(Type type) => TypeLibrary.Register(type);

    /// <summary>Called by <c>regsvr32 /u</c>: removes the type library's registration.</summary>
    [ComUnregisterFunction]
    private static void UnregisterTypeLibrary(Type type) => TypeLibrary.Unregister();

    /// <summary>Whether a COM client is connected to the events (a connection point adds a handler for each).</summary>
    internal bool HasEventSinks => ValueChanged is not null || ConnectionLost is not null || ConnectionRestored is not null;

    internal void RaiseValueChanged(string tag, object value) => ValueChanged?.Invoke(tag, value);

    internal void RaiseConnectionLost(int number, string description) => ConnectionLost?.Invoke(number, description);

    internal void RaiseConnectionRestored(double outageSeconds) => ConnectionRestored?.Invoke(outageSeconds);

    private PlcWatch WatchOrRaise()
        => _watch ?? throw PlcErrors.Raise(PlcErrors.NotOpen, "No watch is running; call Watch first.");

    /// <summary>The unit <see cref="UnitNumber"/> names, on the open link.</summary>
    private IHostLinkUnit OpenUnit()
    {
        lock (_gate)
        {
            HostLinkClient client = _client ?? throw PlcErrors.Raise(PlcErrors.NotOpen, "The link is not open; call Open first.");
            int unitNumber = _unitNumber;
            if (unitNumber is < 0 or > 31)
            {
                throw PlcErrors.Raise(PlcErrors.InvalidArgument, $"UnitNumber {unitNumber} is not a unit number; use 0-31.");
            }

            if (_unit is null || _unitOfView != unitNumber)
            {
                _unit = client.Unit(unitNumber);
                _unitOfView = unitNumber;
            }

            return _unit;
        }
    }

    private T Call<T>(Func<IHostLinkUnit, T> call)
    {
        IHostLinkUnit unit = OpenUnit();
        try
        {
            return call(unit);
        }
        catch (Exception e) when (e is not COMException)
        {
            throw PlcErrors.ToComError(e);
        }
    }

    private void Call(Action<IHostLinkUnit> call) => Call(u =>
    {
        call(u);
        return true;
    });

    /// <summary>
    /// A connection property takes effect at the next <see cref="Open"/>, where the settings' checks name whatever is
    /// wrong with it. Property setters never throw: under Wine 8 an exception thrown from a .NET property setter called
    /// through IDispatch ends the calling process (docs/windows.md), and a VB property grid expects to set values freely.
    /// </summary>
    private static void SetForNextOpen<T>(ref T field, T value) => field = value;

    /// <summary>The settings the properties describe, read as configuration would write them.</summary>
    private HostLinkClientSettings FromProperties()
    {
        string Number(int value) => value.ToString(CultureInfo.InvariantCulture);
        var pairs = new List<KeyValuePair<string, string?>>
        {
            new("Serial:BaudRate", Number(_baudRate)),
            new("Serial:DataBits", Number(_dataBits)),
            new("Serial:StopBits", Number(_stopBits)),
            new("UnitNumber", Number(_unitNumber)),
            new("CommandSet", _commandSet),
            new("TurnaroundAllowance", Number(_turnaroundAllowance) + "ms"),
            new("ReadRetries", Number(_readRetries)),
        };
        if (_host.Length > 0 || _tcpPort != 0)
        {
            pairs.Add(new("Tcp:Host", _host));
            pairs.Add(new("Tcp:Port", Number(_tcpPort)));
        }

        if (_portName.Length > 0)
        {
            pairs.Add(new("Serial:PortName", _portName));
        }

        if (_parity.Length > 0)
        {
            pairs.Add(new("Serial:Parity", ConnectionString.ParityName(_parity)));
        }

        var settings = new HostLinkClientSettings();
        settings.Read(pairs);
        return settings;
    }

    /// <summary>The properties read back what was opened, whichever way it was given.</summary>
    private void TakeProperties(HostLinkClientSettings settings)
    {
        HostLinkClientOptions defaults = new();
        _portName = settings.Serial.PortName ?? "";
        _baudRate = settings.Serial.BaudRate ?? 9600;
        _dataBits = settings.Serial.DataBits ?? 7;
        _parity = (settings.Serial.Parity ?? OmronHostLink.Transports.SerialParity.Even).ToString().Substring(0, 1);
        _stopBits = settings.Serial.StopBits == OmronHostLink.Transports.SerialStopBits.One ? 1 : 2;
        _host = settings.Tcp.Host ?? "";
        _tcpPort = settings.Tcp.Port ?? 0;
        _unitNumber = settings.UnitNumber ?? 0;
        _commandSet = (settings.CommandSet ?? HostLinkCommandSet.CMode).ToString();
        _turnaroundAllowance = (int)(settings.TurnaroundAllowance ?? defaults.TurnaroundAllowance).TotalMilliseconds;
        _readRetries = settings.ReadRetries ?? defaults.ReadRetries;
    }
}
