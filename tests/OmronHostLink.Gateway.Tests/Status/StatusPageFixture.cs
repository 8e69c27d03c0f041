using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Simulator;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// One gateway and one browser for the page's tests: a multidrop line of two simulated PLCs (units 0 and 5) recorded
/// frame by frame, Mosquitto for the MQTT and Sparkplug B outputs, the gateway polling the line with its status page on
/// a free loopback port, and headless Chromium. The tests run in turn (one collection) and each opens its view.
/// </summary>
public sealed class StatusPageFixture : IAsyncLifetime
{
    /// <summary>The poll interval of the tag the live-update test changes.</summary>
    public static readonly TimeSpan SetpointInterval = TimeSpan.FromSeconds(2);

    private MosquittoBroker? _broker;
    private RecordingSimulator? _simulator;
    private StatusGateway? _gateway;
    private ChromiumBrowser? _browser;

    /// <summary>Unit 0: answers throughout.</summary>
    public VirtualPlc Present { get; } = new(new VirtualPlcOptions { Units = [0] });

    /// <summary>Unit 5: answers until the silent-unit test silences it.</summary>
    public VirtualPlc Absent { get; } = new(new VirtualPlcOptions { Units = [5] });

    /// <summary>The line's recording.</summary>
    public RecordingSimulator Simulator => _simulator!;

    /// <summary>The gateway.</summary>
    internal StatusGateway Gateway => _gateway!;

    /// <summary>The browser.</summary>
    internal ChromiumBrowser Browser => _browser!;

    /// <summary>Where the screenshots go: a folder beside the test assembly (the test output).</summary>
    public static string Screenshots => Path.Combine(AppContext.BaseDirectory, "status-page-screenshots");

    /// <inheritdoc/>
    public async Task InitializeAsync()
    {
        Present.WriteWords("D100", [120, unchecked((ushort)-340), 560, 780]);
        Present.WriteWords("D200", [0x0000, 0x41AC]); // 21.5
        Present.WriteWords("D300", PlcWords.FromString("MIX-A7"));
        Present.WriteWords("D10", [1500]);
        Present.WriteWords("CIO10", [0x0005]);
        Absent.WriteWords("D0", [77]);
        _broker = await MosquittoBroker.StartAsync();
        _simulator = await RecordingSimulator.StartAsync(new VirtualPlcLine([Present, Absent]));
        Dictionary<string, string?> config = StatusGateway.Configuration(_simulator);
        config.Remove("HostLink:Links:plc:TurnaroundAllowance");
        // Unit 5's polls time out quickly once it is silent, and it is demoted after two and stays so.
        config["HostLink:Links:plc:TurnaroundAllowance"] = "300ms";
        config["HostLink:Links:plc:Demotion:After"] = "2";
        config["HostLink:Links:plc:Demotion:Period"] = "10min";
        // The line's pace: 5 ms of PLC turnaround, as a real PLC takes at least.
        Present.Options.Turnaround = TimeSpan.FromMilliseconds(5);
        Absent.Options.Turnaround = TimeSpan.FromMilliseconds(5);
        MqttGatewayConfig.Group(config, "levels", "D100", count: 4, intervalMs: 500);
        MqttGatewayConfig.Group(config, "temperature", "D200", type: "float", intervalMs: 500);
        MqttGatewayConfig.Group(config, "recipe", "D300", type: "string", count: 6, intervalMs: 1000);
        MqttGatewayConfig.Group(config, "setpoint", "D10", type: "uint16", intervalMs: (int)SetpointInterval.TotalMilliseconds);
        MqttGatewayConfig.Group(config, "outputs", "CIO10.00", type: "bit", count: 4, intervalMs: 500);
        MqttGatewayConfig.Group(config, "spare", "D0", type: "word", intervalMs: 500, unit: 5);
        foreach ((string key, string? value) in MqttGatewayConfig.Create(_simulator.Port, _broker, "status-page-test").Where(k => k.Key.StartsWith("Mqtt:", StringComparison.Ordinal)))
        {
            config[key] = value;
        }

        config["Sparkplug:Host"] = "127.0.0.1";
        config["Sparkplug:Port"] = _broker.Port.ToString(System.Globalization.CultureInfo.InvariantCulture);
        config["Sparkplug:GroupId"] = "Plant1";
        config["Sparkplug:EdgeNodeId"] = "status-page-test";
        config["Sparkplug:Reconnect:Initial"] = "100ms";
        _gateway = await StatusGateway.StartAsync(_simulator, config);
        _browser = ChromiumBrowser.Start();
    }

    /// <summary>Opens a view of the page (<c>lines</c>, <c>tags</c>, <c>trace</c>, <c>outputs</c>).</summary>
    public void Open(string view, int width = 1280, int height = 900)
    {
        Browser.Session.Manage().Window.Size = new System.Drawing.Size(width, height);
        Browser.Session.Navigate().GoToUrl(new Uri(Gateway.Address, "#" + view));
        // A change of the address's fragment alone does not load the page again: ask for the view, from its top.
        Browser.Script("if (location.hash !== arguments[0]) location.hash = arguments[0]; window.scrollTo(0, 0);", "#" + view);
    }

    /// <summary>Saves a screenshot of the window as <c>{name}.png</c> in <see cref="Screenshots"/>.</summary>
    public string Screenshot(string name)
    {
        string path = Path.Combine(Screenshots, name + ".png");
        Browser.Screenshot(path);
        return path;
    }

    /// <inheritdoc/>
    public async Task DisposeAsync()
    {
        _browser?.Dispose();
        if (_gateway is not null)
        {
            await _gateway.DisposeAsync();
        }

        if (_simulator is not null)
        {
            await _simulator.DisposeAsync();
        }

        if (_broker is not null)
        {
            await _broker.DisposeAsync();
        }
    }
}
