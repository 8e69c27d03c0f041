using System.ComponentModel;
using System.Runtime.ExceptionServices;
using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// A PLC as a form holds it, the way it held Omron's OCX: drop it on a form (or create it in code), set the connection
/// in the designer's property grid, list <see cref="Tags"/> and an <see cref="Interval"/>, call <see cref="Start"/>,
/// and handle <see cref="ValueChanged"/> on the UI thread. Reads and writes go through <see cref="Client"/> — blocking
/// calls from a timer (<c>HostLinkPlc1.Client.ReadWords("D100", 10)</c>, see <see cref="HostLinkSynchronousExtensions"/>)
/// or the asynchronous ones. The form's <c>Dispose</c> stops the watch and closes the port.
/// </summary>
/// <remarks>
/// The connection properties are checked as they are set, by the same rules as <see cref="HostLinkClientSettings"/>,
/// and cannot change once the client exists (after <see cref="Start"/> or the first use of <see cref="Client"/>).
/// Events are raised as <see cref="HostLinkWatcher"/> raises them: on the synchronization context current at
/// <see cref="Start"/>, each handler to its end before the watch goes on; a handler's exception goes to
/// <see cref="Error"/> and the watch goes on (with no <see cref="Error"/> handler it is thrown on the UI thread, where
/// WinForms reports it through <c>Application.ThreadException</c>).
/// </remarks>
[DefaultEvent(nameof(ValueChanged))]
[DefaultProperty(nameof(PortName))]
[Description("An Omron PLC over Host Link: connection settings, watched tags and change events.")]
public class HostLinkPlc : Component
{
    private const string ConnectionCategory = "Connection";
    private const string WatchCategory = "Watch";

    // The connection's defaults are the settings' declared ones (HostLinkClientSettings, HostLinkSerialSettings); the
    // designer's [DefaultValue] attributes must be constants and repeat them (a test compares the two).
    private string _portName = "";
    private int _baudRate = HostLinkSerialSettings.BaudRateSetting.Default!.Value;
    private int _dataBits = HostLinkSerialSettings.DataBitsSetting.Default!.Value;
    private SerialParity _parity = HostLinkSerialSettings.ParitySetting.Default!.Value;
    private SerialStopBits _stopBits = HostLinkSerialSettings.StopBitsSetting.Default!.Value;
    private string _host = "";
    private int _tcpPort;
    private int _unitNumber = HostLinkClientSettings.UnitNumberSetting.Default!.Value;
    private HostLinkCommandSet _commandSet = HostLinkClientSettings.CommandSetSetting.Default!.Value;
    private TimeSpan _turnaroundAllowance = HostLinkClientSettings.TurnaroundAllowanceSetting.Default!.Value;
    private int _readRetries = HostLinkClientSettings.ReadRetriesSetting.Default!.Value;
    private bool _allowReadModifyWriteBits = HostLinkClientSettings.AllowReadModifyWriteBitsSetting.Default!.Value;
    private string[] _tags = [];
    private int _interval = 1000;
    private HostLinkClient? _client;
    private HostLinkWatcher? _watcher;
    private bool _disposed;

    /// <summary>Creates the component; set the connection before <see cref="Start"/> or the first use of <see cref="Client"/>.</summary>
    public HostLinkPlc()
    {
    }

    /// <summary>Creates the component in <paramref name="container"/> (a form's components), which disposes it with the form.</summary>
    /// <param name="container">The container.</param>
    public HostLinkPlc(IContainer container)
        => Guard.NotNull(container).Add(this);

    /// <summary>A watched tag's value changed; after <see cref="Start"/>, every tag is reported once with no old value.</summary>
    [Category(WatchCategory)]
    [Description("A watched tag's value changed (raised on the UI thread).")]
    public event EventHandler<TagValueChangedEventArgs>? ValueChanged;

    /// <summary>A read failed: the PLC or the link is away. Once per outage; the watch keeps trying.</summary>
    [Category(WatchCategory)]
    [Description("The PLC stopped answering; the watch keeps trying.")]
    public event EventHandler<ConnectionLostEventArgs>? ConnectionLost;

    /// <summary>A read succeeded again after <see cref="ConnectionLost"/>.</summary>
    [Category(WatchCategory)]
    [Description("The PLC answers again after an outage.")]
    public event EventHandler<ConnectionRestoredEventArgs>? ConnectionRestored;

    /// <summary>A cycle took longer than <see cref="Interval"/>.</summary>
    [Category(WatchCategory)]
    [Description("A cycle took longer than the interval.")]
    public event EventHandler<WatchOverrunEventArgs>? Overrun;

    /// <summary>A handler threw (the watch goes on), or the watch ended because the component was disposed.</summary>
    [Category(WatchCategory)]
    [Description("An event handler threw; the watch goes on.")]
    public event EventHandler<WatchErrorEventArgs>? Error;

    /// <summary>The local serial port (<c>COM3</c>, <c>/dev/ttyUSB0</c>); empty when <see cref="Host"/> is used.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue("")]
    [Description("The serial port: COM3, /dev/ttyUSB0. Leave empty to use Host and TcpPort.")]
    public string PortName
    {
        get => _portName;
        set => Set(ref _portName, value ?? "", v => v.Length == 0 ? null : SettingRules.PortName(v));
    }

    /// <summary>Line speed in bits per second. Default 9600 (the PLC's Host Link port default).</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(SerialLineSettings.DefaultBaudRate)]
    [Description("Line speed in bits per second; the PLC's Host Link port setting.")]
    public int BaudRate
    {
        get => _baudRate;
        set => Set(ref _baudRate, value, SettingRules.BaudRate);
    }

    /// <summary>Data bits, 7 or 8. Default 7.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(7)]
    [Description("Data bits: 7 (default) or 8.")]
    public int DataBits
    {
        get => _dataBits;
        set => Set(ref _dataBits, value, SettingRules.DataBits);
    }

    /// <summary>Parity. Default Even.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(SerialParity.Even)]
    [Description("Parity: Even (default), Odd or None.")]
    public SerialParity Parity
    {
        get => _parity;
        set => Set(ref _parity, value, SettingRules.Defined);
    }

    /// <summary>Stop bits. Default Two.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(SerialStopBits.Two)]
    [Description("Stop bits: Two (default) or One.")]
    public SerialStopBits StopBits
    {
        get => _stopBits;
        set => Set(ref _stopBits, value, SettingRules.Defined);
    }

    /// <summary>A serial-device server's host name or address (with <see cref="TcpPort"/>) instead of a local port.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue("")]
    [Description("A serial-device server's host or address, with TcpPort; leave empty for a local PortName.")]
    public string Host
    {
        get => _host;
        set => Set(ref _host, value ?? "", v => v.Length == 0 ? null : SettingRules.Host(v));
    }

    /// <summary>The serial-device server's TCP port.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(0)]
    [Description("The serial-device server's TCP port (1-65535).")]
    public int TcpPort
    {
        get => _tcpPort;
        set => Set(ref _tcpPort, value, v => v == 0 ? null : SettingRules.TcpPort(v));
    }

    /// <summary>The PLC's unit number, 0-31, as set on its Host Link port. Default 0.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(0)]
    [Description("The PLC's unit number (0-31), as set on its Host Link port.")]
    public int UnitNumber
    {
        get => _unitNumber;
        set => Set(ref _unitNumber, value, SettingRules.UnitNumber);
    }

    /// <summary>C-mode (default, every Host Link PLC) or FINS (CS/CJ/CP: the work area, bit writes); see <see cref="HostLinkClientOptions.CommandSet"/>.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(HostLinkCommandSet.CMode)]
    [Description("CMode (default) or Fins (CS/CJ/CP: needed for W bits and bit writes).")]
    public HostLinkCommandSet CommandSet
    {
        get => _commandSet;
        set => Set(ref _commandSet, value, SettingRules.Defined);
    }

    /// <summary>How long the PLC may take to start answering, on top of the frame's wire time. Default 300 ms.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(typeof(TimeSpan), "00:00:00.3")]
    [Description("How long the PLC may take to start answering, on top of the wire time (default 00:00:00.3).")]
    public TimeSpan TurnaroundAllowance
    {
        get => _turnaroundAllowance;
        set => Set(ref _turnaroundAllowance, value, SettingRules.TurnaroundAllowance);
    }

    /// <summary>How many times a read is repeated after a timeout or a damaged frame, 0-10. Default 2.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(2)]
    [Description("How many times a read is repeated after a timeout or damaged frame (0-10, default 2).")]
    public int ReadRetries
    {
        get => _readRetries;
        set => Set(ref _readRetries, value, SettingRules.Retries);
    }

    /// <summary>Lets a C-mode PLC's bits be written by reading, changing and writing back the word; see <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/>.</summary>
    [Category(ConnectionCategory)]
    [DefaultValue(false)]
    [Description("C-mode bit writes as read-word, change bit, write-word (the PLC program's changes in between are lost).")]
    public bool AllowReadModifyWriteBits
    {
        get => _allowReadModifyWriteBits;
        set => Set(ref _allowReadModifyWriteBits, value, _ => null);
    }

    /// <summary>
    /// The tags <see cref="Start"/> watches, as text: <c>D100</c> (a word), <c>D100:float</c>, <c>D20:bcd</c>,
    /// <c>CIO 10.03</c> (a bit), <c>T5:bit</c>. Checked at <see cref="Start"/>.
    /// </summary>
    [Category(WatchCategory)]
    [Description("Tags to watch: D100, D100:float, D20:bcd, CIO 10.03, T5:bit.")]
    [Editor("System.Windows.Forms.Design.StringArrayEditor, System.Design", "System.Drawing.Design.UITypeEditor, System.Drawing")]
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Performance", "CA1819:Properties should not return arrays", Justification = "A designer edits a string array; the array is copied both ways.")]
    public string[] Tags
    {
        get => (string[])_tags.Clone();
        set => _tags = value is null ? [] : (string[])value.Clone();
    }

    /// <summary>Milliseconds from the start of one cycle to the start of the next, as a WinForms <c>Timer.Interval</c>. Default 1000.</summary>
    [Category(WatchCategory)]
    [DefaultValue(1000)]
    [Description("Milliseconds from the start of one read cycle to the next (default 1000).")]
    public int Interval
    {
        get => _interval;
        set
        {
            if (value < 0)
            {
                throw new ArgumentOutOfRangeException(nameof(Interval), value, $"Interval is in milliseconds, 0 (back to back) or more; it was {value}.");
            }

            _interval = value;
        }
    }

    /// <summary>Whether the tags are being watched.</summary>
    [Browsable(false)]
    [DesignerSerializationVisibility(DesignerSerializationVisibility.Hidden)]
    public bool IsWatching => _watcher is { IsRunning: true };

    /// <summary>
    /// The client the properties describe, made on first use (nothing opens until the first exchange): read and write
    /// through it, blocking (<c>Client.ReadWords("D100", 10)</c>) or asynchronously. The connection properties cannot
    /// change after this.
    /// </summary>
    /// <exception cref="InvalidOperationException">No link is set (<see cref="PortName"/>, or <see cref="Host"/> and <see cref="TcpPort"/>), or both are.</exception>
    /// <exception cref="ObjectDisposedException">The component was disposed.</exception>
    [Browsable(false)]
    [DesignerSerializationVisibility(DesignerSerializationVisibility.Hidden)]
    public HostLinkClient Client => _disposed ? throw new ObjectDisposedException(nameof(HostLinkPlc)) : _client ??= CreateClient();

    /// <summary>
    /// Starts watching <see cref="Tags"/> every <see cref="Interval"/>, raising the events on the current thread's
    /// synchronization context (call it from the form, e.g. in <c>Load</c>). Does nothing while watching.
    /// </summary>
    /// <exception cref="InvalidOperationException">No tags, or no link is set.</exception>
    /// <exception cref="FormatException">A tag is not valid; the message names it.</exception>
    /// <exception cref="ArgumentException">A tag cannot be read with <see cref="CommandSet"/> (the work area with C-mode).</exception>
    public void Start()
    {
        if (IsWatching)
        {
            return;
        }

        if (_tags.Length == 0)
        {
            throw new InvalidOperationException("Set Tags (such as D100 or D100:float) before Start.");
        }

        var watcher = new HostLinkWatcher(Client, _tags, TimeSpan.FromMilliseconds(_interval));
        watcher.ValueChanged += (_, e) => ValueChanged?.Invoke(this, e);
        watcher.ConnectionLost += (_, e) => ConnectionLost?.Invoke(this, e);
        watcher.ConnectionRestored += (_, e) => ConnectionRestored?.Invoke(this, e);
        watcher.Overrun += (_, e) => Overrun?.Invoke(this, e);
        watcher.Error += (_, e) =>
        {
            if (Error is { } handlers)
            {
                handlers(this, e);
                return;
            }

            // No handler here: the watcher throws it on the UI thread.
            ExceptionDispatchInfo.Capture(e.Exception).Throw();
        };
        _watcher?.Dispose();
        _watcher = watcher;
        watcher.Start();
    }

    /// <summary>Stops watching; returns at once (safe on the UI thread). The client stays open for reads and writes.</summary>
    public void Stop() => _watcher?.Stop();

    /// <summary>Stops watching and closes the port or socket at once.</summary>
    /// <param name="disposing">True when called from <see cref="Component.Dispose()"/>.</param>
    protected override void Dispose(bool disposing)
    {
        if (disposing)
        {
            _disposed = true;
            _watcher?.Dispose();
            _client?.Dispose();
        }

        base.Dispose(disposing);
    }

    private HostLinkClient CreateClient()
    {
        bool serial = _portName.Length > 0;
        bool tcp = _host.Length > 0 || _tcpPort != 0;
        if (serial == tcp)
        {
            throw new InvalidOperationException(serial
                ? $"Set PortName or Host and TcpPort, not both (PortName is {_portName}, Host is {_host})."
                : "Set PortName (a serial port such as COM3) or Host and TcpPort (a serial-device server) before Start or the first use of Client.");
        }

        if (tcp && (_host.Length == 0 || _tcpPort == 0))
        {
            throw new InvalidOperationException($"A serial-device server needs both Host and TcpPort (Host is '{_host}', TcpPort is {_tcpPort}).");
        }

        var settings = new HostLinkClientSettings
        {
            UnitNumber = _unitNumber,
            CommandSet = _commandSet,
            TurnaroundAllowance = _turnaroundAllowance,
            ReadRetries = _readRetries,
            AllowReadModifyWriteBits = _allowReadModifyWriteBits,
        };
        settings.Serial.PortName = serial ? _portName : null;
        settings.Serial.BaudRate = _baudRate;
        settings.Serial.DataBits = _dataBits;
        settings.Serial.Parity = _parity;
        settings.Serial.StopBits = _stopBits;
        if (tcp)
        {
            settings.Tcp.Host = _host;
            settings.Tcp.Port = _tcpPort;
        }

        return settings.CreateClient(o => o.LinkName = Site?.Name);
    }

    /// <summary>Sets a connection property after checking it by its rule (null: fine); refused once the client exists.</summary>
    private void Set<T>(ref T field, T value, Func<T, string?> rule, [System.Runtime.CompilerServices.CallerMemberName] string property = "")
    {
        if (_client is not null)
        {
            throw new InvalidOperationException($"{property} cannot change once the client exists (after Start or the first use of Client); set the connection first.");
        }

        if (rule(value) is { } problem)
        {
            throw new ArgumentOutOfRangeException(property, value, $"{property}: {problem}.");
        }

        field = value;
    }
}
