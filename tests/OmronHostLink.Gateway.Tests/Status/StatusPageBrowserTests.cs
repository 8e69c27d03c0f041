using Microsoft.Extensions.DependencyInjection;
using OmronHostLink.Gateway.Status;
using OmronHostLink.Gateway.Tests.Mqtt;
using OpenQA.Selenium;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// The status page in a real browser (headless Chromium driven over WebDriver) against a gateway polling a simulated
/// multidrop line: the views list the links, units and tags with the simulator's values, a value changed in the
/// simulator appears within two poll intervals without a reload, a unit made silent shows comm-error then demoted, the
/// line trace shows the frames the simulator received and sent, and the outputs show their broker. A screenshot of each
/// view is saved beside the test assembly, in status-page-screenshots/.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class StatusPageBrowserTests(StatusPageFixture page, ITestOutputHelper output) : IClassFixture<StatusPageFixture>
{
    [Fact]
    public async Task Lines_lists_the_link_and_its_units_with_their_figures()
    {
        page.Open("lines");
        ChromiumBrowser browser = page.Browser;
        await browser.Until(b => Text(b, "article[data-link='plc'] tr[data-unit='0'] .state") == "online", "unit 0 of link plc is shown online");
        string? endpoint = Text(browser, "article[data-link='plc'] .endpoint");
        endpoint.Should().Be($"127.0.0.1:{page.Simulator.Port}");
        Text(browser, "article[data-link='plc'] .line").Should().Be("115200 bps on the serial side of the device server");
        Attributes(browser, "article[data-link='plc'] tr[data-unit]", "data-unit").Should().Equal(["0", "5"], "both units of the line are listed");
        // The rate appears once two samples are apart, and the transactions keep counting.
        string rate = await browser.Until(b => Text(b, "article[data-link='plc'] .rate") is { } r && r != "—" ? r : null, "transactions per second are shown");
        double.Parse(rate, System.Globalization.CultureInfo.InvariantCulture).Should().BePositive();
        long first = long.Parse(Text(browser, "article[data-link='plc'] .transactions")!, System.Globalization.CultureInfo.InvariantCulture);
        await browser.Until(b => long.Parse(Text(b, "article[data-link='plc'] .transactions")!, System.Globalization.CultureInfo.InvariantCulture) > first, "the transactions count up without a reload");
        Text(browser, "article[data-link='plc'] table.scan-classes").Should().Contain("setpoint").And.Contain("levels");
        // Each scan class shows its measured cycle beside its interval once it has read.
        string cycle = await browser.Until(b => Text(b, "article[data-link='plc'] table.scan-classes tr[data-scan-unit='0'] .cycle") is { } c && !c.StartsWith('—') ? c : null, "the measured cycle of unit 0's scan class is shown");
        cycle.Should().MatchRegex(@"^\d+(\.\d+)? ms / \d+(\.\d+)? ms$");
        output.WriteLine(page.Screenshot("lines"));
    }

    [Fact]
    public async Task Tags_lists_every_tag_with_the_simulators_values_and_a_change_appears_within_two_intervals()
    {
        page.Open("tags");
        ChromiumBrowser browser = page.Browser;
        await browser.Until(b => Text(b, "tr[data-tag='plc/0/levels'] .value") == "[120, -340, 560, 780]", "levels shows the simulator's words");
        await browser.Until(b => Text(b, "tr[data-tag='plc/0/temperature'] .value") == "21.5", "temperature shows the REAL");
        await browser.Until(b => Text(b, "tr[data-tag='plc/0/recipe'] .value") == "\"MIX-A7\"", "recipe shows the text");
        await browser.Until(b => Text(b, "tr[data-tag='plc/0/outputs'] .value") == "[1 (on), 0 (off), 1 (on), 0 (off)]", "outputs shows the bits");
        await browser.Until(b => Text(b, "tr[data-tag='plc/0/setpoint'] .value") == "1500", "setpoint shows its value");
        browser.Session.FindElements(By.CssSelector("#tags tbody tr")).Should().HaveCount(page.Gateway.Host.Services.GetRequiredService<TagBoard>().Count);
        Text(browser, "tr[data-tag='plc/0/setpoint'] .quality").Should().Be("good");

        // Filtered: only the tags that match.
        IWebElement filter = browser.Session.FindElement(By.Id("tag-filter"));
        filter.SendKeys("temp");
        await browser.Until(b => b.Session.FindElements(By.CssSelector("#tags tbody tr")).Count(r => r.Displayed) == 1, "the filter leaves one tag");
        filter.Clear();
        filter.SendKeys(" ");
        filter.SendKeys(Keys.Backspace);
        await browser.Until(b => b.Session.FindElements(By.CssSelector("#tags tbody tr")).All(r => r.Displayed), "every tag is shown again");

        // The page records when the cell first shows the new value; the test, when it changed the PLC's memory.
        browser.Script("""
            window.statusTestLoad = 'before the change';
            window.statusTestSeen = null;
            const cell = () => document.querySelector("tr[data-tag='plc/0/setpoint'] .value");
            new MutationObserver(() => { if (!window.statusTestSeen && cell().textContent === arguments[0]) window.statusTestSeen = Date.now(); })
              .observe(document.querySelector('#tags tbody'), { subtree: true, childList: true, characterData: true });
            """, "2345");
        long changed = DateTimeOffset.UtcNow.ToUnixTimeMilliseconds();
        page.Present.WriteWords("D10", [2345]);
        long seen = (await browser.Until(b => b.Script("return window.statusTestSeen;") is long at ? at : (long?)null, "the new value appears", TimeSpan.FromSeconds(60))) ?? throw new InvalidOperationException("no time");
        TimeSpan delay = TimeSpan.FromMilliseconds(seen - changed);
        output.WriteLine($"setpoint changed in the simulator; shown by the page {delay.TotalMilliseconds:0} ms later (interval {StatusPageFixture.SetpointInterval.TotalMilliseconds} ms)");
        browser.Script("return window.statusTestLoad;").Should().Be("before the change", "the page was not loaded again");
        delay.Should().BeLessThanOrEqualTo(2 * StatusPageFixture.SetpointInterval, "a change appears within two poll intervals");
        Text(browser, "tr[data-tag='plc/0/setpoint'] .age").Should().NotBe("—");
        Attributes(browser, "tr[data-tag='plc/0/setpoint'] .spark polyline", "points").Should().ContainSingle("a numeric tag has its sparkline")
            .Which.Split(' ').Should().HaveCountGreaterThanOrEqualTo(2);
        Attributes(browser, "tr[data-tag='plc/0/levels'] .spark polyline", "points").Should().BeEmpty("several values have none");
        output.WriteLine(page.Screenshot("tags"));

        // At a panel, on a phone.
        page.Open("tags", 412, 915);
        await browser.Until(b => Text(b, "tr[data-tag='plc/0/setpoint'] .value") == "2345", "the phone-sized page shows the tags");
        output.WriteLine(page.Screenshot("tags-phone"));
        page.Open("tags");
    }

    [Fact]
    public async Task A_unit_made_silent_shows_comm_error_then_demoted()
    {
        page.Open("lines");
        ChromiumBrowser browser = page.Browser;
        await browser.Until(b => Text(b, "article[data-link='plc'] tr[data-unit='5'] .state") == "online", "unit 5 is shown online");
        // Every state the page shows for unit 5, in order, however the view is drawn again.
        browser.Script("""
            window.statusTestStates = [];
            const note = () => {
              const cell = document.querySelector("article[data-link='plc'] tr[data-unit='5'] .state");
              const state = cell && cell.textContent;
              if (state && window.statusTestStates[window.statusTestStates.length - 1] !== state) window.statusTestStates.push(state);
            };
            note();
            new MutationObserver(note).observe(document.getElementById('lines'), { subtree: true, childList: true, characterData: true });
            """);

        page.Absent.Options.Faults.Drop = 1;
        await browser.Until(b => Text(b, "article[data-link='plc'] tr[data-unit='5'] .state") == "demoted", "unit 5 is shown demoted", TimeSpan.FromSeconds(90));
        var states = ((IEnumerable<object>)browser.Script("return window.statusTestStates;")!).Cast<string>().ToList();
        output.WriteLine("unit 5 shown: " + string.Join(" -> ", states));
        states.Should().Equal(["online", "comm-error", "demoted"], "the page showed the unit comm-error, then demoted");
        Attributes(browser, "article[data-link='plc'] tr[data-unit='5'] .events li", "data-state").Should().ContainInOrder("comm-error", "demoted");
        Text(browser, "article[data-link='plc'] tr[data-unit='5'] .last-error").Should().Contain("No answer from unit 05");
        Text(browser, "article[data-link='plc'] tr[data-unit='0'] .state").Should().Be("online", "the other unit answers all along");
        output.WriteLine(page.Screenshot("lines-demoted"));
    }

    [Fact]
    public async Task The_line_trace_is_off_until_started_and_shows_the_frames_the_simulator_received_and_sent()
    {
        LineTraces traces = page.Gateway.Host.Services.GetRequiredService<LineTraces>();
        traces.IsTracing("plc").Should().BeFalse("the trace is off unless asked for");
        page.Open("trace");
        ChromiumBrowser browser = page.Browser;
        await browser.Until(b => b.Session.FindElements(By.CssSelector("#trace-link option")).Count == 1, "the link is offered");
        traces.IsTracing("plc").Should().BeFalse("opening the view does not start it");

        browser.Session.FindElement(By.Id("trace-toggle")).Click();
        await MqttGatewayConfig.Eventually(() => traces.IsTracing("plc"), "the trace of plc is on", page.Gateway.Logs);
        await browser.Until(b => b.Session.FindElements(By.CssSelector("#trace tbody tr[data-seq]")).Count >= 30, "30 frames are shown", TimeSpan.FromSeconds(90));
        browser.Session.FindElement(By.Id("trace-toggle")).Click();
        await MqttGatewayConfig.Eventually(() => !traces.IsTracing("plc"), "paused, the trace of plc is off", page.Gateway.Logs);
        await browser.Until(b => b.Session.FindElement(By.Id("trace-toggle")).Text == "Resume", "the page says it is paused");
        output.WriteLine(page.Screenshot("trace"));

        // Oldest first, as the line carried them.
        var rows = ((IEnumerable<object>)browser.Script("""
            return [...document.querySelectorAll('#trace tbody tr[data-seq]')].reverse().map(r => [
              r.dataset.seq, r.classList.contains('dir-out') ? 'out' : 'in', r.querySelector('.text code').textContent, r.querySelector('.explained').textContent]);
            """)!).Cast<IEnumerable<object>>().Select(r => r.Cast<string>().ToArray()).ToList();
        rows.Should().HaveCountGreaterThanOrEqualTo(30);
        rows.Select(r => long.Parse(r[0], System.Globalization.CultureInfo.InvariantCulture)).Should().BeInAscendingOrder();
        string[] sent = rows.Where(r => r[1] == "out").Select(r => Frame(r[2])).ToArray();
        string[] answered = rows.Where(r => r[1] == "in").Select(r => Frame(r[2])).ToArray();
        sent.Should().NotBeEmpty();
        answered.Should().NotBeEmpty();
        IsRunWithin(sent, page.Simulator.Received).Should().BeTrue("the frames out are those the simulator received, one after the other:\n{0}", string.Join("\n", sent));
        IsInOrderWithin(answered, page.Simulator.Sent).Should().BeTrue("the frames in are those the simulator sent, in order:\n{0}", string.Join("\n", answered));
        rows.Should().Contain(r => r[3].Contains("DM AREA READ", StringComparison.Ordinal), "frames are explained as hostlink explain does");
        rows.Should().Contain(r => r[1] == "in" && r[3].Contains("words: [", StringComparison.Ordinal), "answers are decoded");
    }

    [Fact]
    public async Task Outputs_shows_each_outputs_broker_connection_and_queue()
    {
        page.Open("outputs");
        ChromiumBrowser browser = page.Browser;
        string server = $"127.0.0.1:{page.Gateway.Config["Mqtt:Port"]}";
        await browser.Until(b => Text(b, "article[data-output='MQTT'] .state") == "connected", "MQTT is shown connected");
        Text(browser, "article[data-output='MQTT'] .server").Should().Be(server);
        await browser.Until(b => Text(b, "article[data-output='MQTT'] .last-publish") != "none yet", "MQTT's last publish is shown");
        Text(browser, "article[data-output='MQTT'] .queue").Should().MatchRegex("^[0-9]+$");
        Text(browser, "article[data-output='MQTT'] .at-risk").Should().MatchRegex("^[0-9]+$");
        await browser.Until(b => Text(b, "article[data-output='Sparkplug B'] .state") == "online (births sent)", "Sparkplug B is shown online");
        Text(browser, "article[data-output='Sparkplug B'] .server").Should().Be(server);
        Text(browser, "article[data-output='Sparkplug B'] .queue").Should().Be("no queue");
        output.WriteLine(page.Screenshot("outputs"));
    }

    /// <summary>
    /// The text of the element <paramref name="css"/> selects, spaces collapsed; null when there is none. Read in the page
    /// in one step: a view drawn again between finding an element and reading it would leave a stale reference.
    /// </summary>
    private static string? Text(ChromiumBrowser browser, string css)
        => browser.Script("const e = document.querySelector(arguments[0]); return e ? e.textContent.replace(/\\s+/g, ' ').trim() : null;", css) as string;

    /// <summary>The values of <paramref name="attribute"/> of the elements <paramref name="css"/> selects, read in one step.</summary>
    private static List<string> Attributes(ChromiumBrowser browser, string css, string attribute)
        => ((IEnumerable<object>)browser.Script("return [...document.querySelectorAll(arguments[0])].map(e => e.getAttribute(arguments[1]));", css, attribute)!).Cast<string>().ToList();

    /// <summary>A frame as the trace shows it (CR written <c>\r</c>) as the simulator logs it (without the CR).</summary>
    private static string Frame(string shown) => shown.EndsWith("\\r", StringComparison.Ordinal) ? shown[..^2] : shown;

    /// <summary>Whether <paramref name="part"/> appears in <paramref name="whole"/> as a run, one after the other.</summary>
    private static bool IsRunWithin(IReadOnlyList<string> part, IReadOnlyList<string> whole)
        => Enumerable.Range(0, Math.Max(0, whole.Count - part.Count + 1)).Any(i => part.Select((f, j) => whole[i + j] == f).All(same => same));

    /// <summary>Whether <paramref name="part"/> appears in <paramref name="whole"/> in the same order (not necessarily next to each other).</summary>
    private static bool IsInOrderWithin(IReadOnlyList<string> part, IReadOnlyList<string> whole)
    {
        int at = 0;
        foreach (string frame in part)
        {
            while (at < whole.Count && whole[at] != frame)
            {
                at++;
            }

            if (at++ >= whole.Count)
            {
                return false;
            }
        }

        return true;
    }
}
