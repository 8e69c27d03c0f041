using System.Globalization;
using System.Net;
using System.Net.Http.Headers;
using System.Text;
using Microsoft.AspNetCore.Routing;
using Microsoft.Extensions.DependencyInjection;
using OmronHostLink.Gateway.Status;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// The status page's defences, against a gateway polling a recording simulator: it listens on 127.0.0.1 unless told
/// otherwise, every request needs the token once one is set (401 without it), a page elsewhere cannot reach it under a
/// name of its own, and no route with any method changes anything in a PLC — only reads reach the simulator, and its
/// memory stays as it was.
/// </summary>
public sealed class StatusSecurityTests
{
    private const string Token = "0123456789abcdef-test-token";

    /// <summary>Every method a client may send; the page answers GET and HEAD only.</summary>
    private static readonly string[] Methods = ["GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS", "TRACE", "PROPFIND", "MKCOL", "LOCK", "COPY", "MOVE"];

    [Fact]
    public async Task By_default_it_listens_on_127_0_0_1_only()
    {
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlc(new VirtualPlcOptions { Units = [0] }));
        Dictionary<string, string?> config = StatusGateway.Configuration(simulator);
        MqttGatewayConfig.Group(config, "levels", "D100", intervalMs: 200);
        await using StatusGateway gateway = await StatusGateway.StartAsync(simulator, config);

        gateway.Server.EndPoint!.Address.Should().Be(IPAddress.Loopback);
        int port = gateway.Server.EndPoint.Port;
        if (OperatingSystem.IsLinux())
        {
            // The kernel's own list of listening sockets: 127.0.0.1 and no other address on the page's port.
            string hexPort = port.ToString("X4", CultureInfo.InvariantCulture);
            string[] listening = ListeningSockets().Where(s => s.EndsWith(":" + hexPort, StringComparison.Ordinal)).ToArray();
            listening.Should().Equal(["0100007F:" + hexPort], "only 127.0.0.1 listens on port {0}", port);
        }

        using HttpClient client = gateway.Client();
        (await client.GetAsync("api/lines")).StatusCode.Should().Be(HttpStatusCode.OK, "no token is needed on loopback without one configured");
    }

    [Fact]
    public async Task Under_a_name_other_than_localhost_it_answers_nothing_without_a_token()
    {
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlc(new VirtualPlcOptions { Units = [0] }));
        Dictionary<string, string?> config = StatusGateway.Configuration(simulator);
        MqttGatewayConfig.Group(config, "levels", "D100", intervalMs: 200);
        await using StatusGateway gateway = await StatusGateway.StartAsync(simulator, config);
        using HttpClient client = gateway.Client();

        // A page on another site that points a name of its own at 127.0.0.1 (DNS rebinding) sends that name.
        using var request = new HttpRequestMessage(HttpMethod.Get, "api/tags");
        request.Headers.Host = "attacker.example";
        HttpResponseMessage refused = await client.SendAsync(request);
        refused.StatusCode.Should().Be(HttpStatusCode.BadRequest);
        (await refused.Content.ReadAsStringAsync()).Should().NotContain("levels");

        using var local = new HttpRequestMessage(HttpMethod.Get, "api/tags");
        local.Headers.Host = $"localhost:{gateway.Server.EndPoint!.Port}";
        (await client.SendAsync(local)).StatusCode.Should().Be(HttpStatusCode.OK);
    }

    [Fact]
    public async Task With_a_token_a_request_without_it_gets_401_and_with_it_the_page()
    {
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlc(new VirtualPlcOptions { Units = [0] }));
        Dictionary<string, string?> config = StatusGateway.Configuration(simulator);
        config["Status:AccessToken"] = Token;
        MqttGatewayConfig.Group(config, "levels", "D100", intervalMs: 200);
        await using StatusGateway gateway = await StatusGateway.StartAsync(simulator, config);
        using HttpClient client = gateway.Client(allowRedirect: false);

        foreach (string path in Paths(gateway.Server.Routes))
        {
            HttpResponseMessage bare = await client.GetAsync(path, HttpCompletionOption.ResponseHeadersRead);
            bare.StatusCode.Should().Be(HttpStatusCode.Unauthorized, "GET {0} without the token", path);
            bare.Headers.WwwAuthenticate.Should().ContainSingle().Which.Scheme.Should().Be("Bearer");
            (await bare.Content.ReadAsStringAsync()).Should().NotContain("levels").And.Contain("token");

            using var wrong = new HttpRequestMessage(HttpMethod.Get, path);
            wrong.Headers.Authorization = new AuthenticationHeaderValue("Bearer", Token + "x");
            (await client.SendAsync(wrong, HttpCompletionOption.ResponseHeadersRead)).StatusCode.Should().Be(HttpStatusCode.Unauthorized, "GET {0} with a wrong token", path);

            using var right = new HttpRequestMessage(HttpMethod.Get, path);
            right.Headers.Authorization = new AuthenticationHeaderValue("Bearer", Token);
            using HttpResponseMessage ok = await client.SendAsync(right, HttpCompletionOption.ResponseHeadersRead);
            ok.StatusCode.Should().Be(HttpStatusCode.OK, "GET {0} with the token", path);
        }

        // A browser opens the page once with the token in the address: it is kept in a cookie, out of the address bar.
        HttpResponseMessage opened = await client.GetAsync($"?token={Token}");
        opened.StatusCode.Should().Be(HttpStatusCode.SeeOther);
        opened.Headers.Location!.ToString().Should().Be("/");
        string cookie = opened.Headers.GetValues("Set-Cookie").Single();
        cookie.Should().Contain("httponly").And.Contain("samesite=strict").And.NotContain(Token);
        using var withCookie = new HttpRequestMessage(HttpMethod.Get, "api/lines");
        withCookie.Headers.Add("Cookie", cookie.Split(';')[0]);
        (await client.SendAsync(withCookie)).StatusCode.Should().Be(HttpStatusCode.OK);
        (await client.GetAsync("?token=wrong-token-0123456789")).StatusCode.Should().Be(HttpStatusCode.Unauthorized);
    }

    [Fact]
    public async Task No_route_with_any_method_changes_PLC_memory_or_sends_anything_but_reads()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0] });
        plc.WriteWords("D100", [1, 2, 3, 4]);
        plc.WriteWords("D200", [0x0000, 0x41AC]);
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = StatusGateway.Configuration(simulator);
        config["Status:AccessToken"] = Token;
        MqttGatewayConfig.Group(config, "levels", "D100", count: 4, intervalMs: 100, writable: true);
        MqttGatewayConfig.Group(config, "temperature", "D200", type: "float", intervalMs: 100, writable: true);
        ushort[] before = plc.ReadWords("D0", 1000);
        await using StatusGateway gateway = await StatusGateway.StartAsync(simulator, config);
        using HttpClient client = gateway.Client(allowRedirect: false);
        client.DefaultRequestHeaders.Authorization = new AuthenticationHeaderValue("Bearer", Token);
        IReadOnlyList<RouteEndpoint> routes = gateway.Server.Routes;
        routes.Should().NotBeEmpty();

        int tried = 0;
        foreach (string path in Paths(routes).Concat(["api/levels", "api/tags/levels", "api/write", "set"]))
        {
            foreach (string method in Methods)
            {
                // A body such as a write would carry, and the query a form might.
                using var request = new HttpRequestMessage(new HttpMethod(method), path + (path.Contains('?', StringComparison.Ordinal) ? "&" : "?") + "value=99&tag=levels")
                {
                    Content = method is "GET" or "HEAD" ? null : new StringContent("{\"link\":\"plc\",\"unit\":0,\"tag\":\"levels\",\"value\":[9,9,9,9]}", Encoding.UTF8, "application/json"),
                };
                using HttpResponseMessage response = await client.SendAsync(request, HttpCompletionOption.ResponseHeadersRead);
                tried++;
                if (method is "GET" or "HEAD")
                {
                    response.StatusCode.Should().BeOneOf([HttpStatusCode.OK, HttpStatusCode.NotFound], "{0} {1}", method, path);
                }
                else
                {
                    response.StatusCode.Should().Be(HttpStatusCode.MethodNotAllowed, "{0} {1}: the page is read-only", method, path);
                    response.Content.Headers.Allow.Should().BeEquivalentTo(["GET", "HEAD"]);
                }
            }
        }

        // The routes were tried while the links polled: the polls after them read what was there before.
        long answers = simulator.Answers;
        await simulator.WaitForAnswersAsync(answers, 4, TimeSpan.FromSeconds(30));
        tried.Should().Be((Paths(routes).Count() + 4) * Methods.Length);
        plc.ReadWords("D0", 1000).Should().Equal(before, "no route changed PLC memory");
        string[] notReads = simulator.Received.Where(f => !IsRead(f)).Distinct().ToArray();
        notReads.Should().BeEmpty("only read commands (and the registration of the links' compound reads) reach the PLC (by the command table's effect of each header)");
        simulator.Received.Should().Contain(f => f.StartsWith("@00RD0100", StringComparison.Ordinal), "the links polled meanwhile");
    }

    [Fact]
    public async Task Open_streams_end_when_the_gateway_stops_and_the_trace_tap_goes_with_them()
    {
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlc(new VirtualPlcOptions { Units = [0] }));
        Dictionary<string, string?> config = StatusGateway.Configuration(simulator);
        MqttGatewayConfig.Group(config, "levels", "D100", intervalMs: 50);
        StatusGateway gateway = await StatusGateway.StartAsync(simulator, config);
        using HttpClient client = gateway.Client();
        LineTraces traces = gateway.Host.Services.GetRequiredService<LineTraces>();
        using HttpResponseMessage tags = await client.GetAsync("api/tags/events", HttpCompletionOption.ResponseHeadersRead);
        using HttpResponseMessage trace = await client.GetAsync("api/trace/plc/events", HttpCompletionOption.ResponseHeadersRead);
        tags.Content.Headers.ContentType!.MediaType.Should().Be("text/event-stream");
        await using Stream tagStream = await tags.Content.ReadAsStreamAsync();
        await using Stream traceStream = await trace.Content.ReadAsStreamAsync();
        (await ReadEventAsync(tagStream)).Should().StartWith("event: snapshot\ndata: {");
        await MqttGatewayConfig.Eventually(() => traces.IsTracing("plc"), "the trace of plc is on while its stream is open", gateway.Logs);

        // The host gives its stop 10 s; open pages must not hold it that long.
        var stopping = System.Diagnostics.Stopwatch.StartNew();
        await gateway.DisposeAsync();
        stopping.Elapsed.Should().BeLessThan(TimeSpan.FromSeconds(8), "the streams end when the gateway stops");
        (await DrainAsync(tagStream)).Should().BeTrue("the tags stream ended");
        (await DrainAsync(traceStream)).Should().BeTrue("the trace stream ended");
        traces.IsTracing("plc").Should().BeFalse("the tap goes with the last stream");
    }

    /// <summary>Reads one server-sent event (up to its blank line).</summary>
    private static async Task<string> ReadEventAsync(Stream stream)
    {
        var text = new StringBuilder();
        var buffer = new byte[4096];
        while (!text.ToString().Contains("\n\n", StringComparison.Ordinal))
        {
            int n = await stream.ReadAsync(buffer);
            if (n == 0)
            {
                break;
            }

            text.Append(Encoding.UTF8.GetString(buffer, 0, n));
        }

        return text.ToString();
    }

    /// <summary>Reads to the stream's end; true when it ended (or the connection closed) rather than waiting on.</summary>
    private static async Task<bool> DrainAsync(Stream stream)
    {
        using var patience = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        var buffer = new byte[4096];
        try
        {
            while (await stream.ReadAsync(buffer, patience.Token) > 0)
            {
            }

            return true;
        }
        catch (IOException)
        {
            return true;
        }
        catch (OperationCanceledException)
        {
            return false;
        }
    }

    /// <summary>Each route with its parameter filled (the link <c>plc</c>), and the page's files.</summary>
    private static IEnumerable<string> Paths(IReadOnlyList<RouteEndpoint> routes)
        => new[] { "", "index.html", "status.js", "status.css" }
            .Concat(routes.Select(r => r.RoutePattern.RawText!.TrimStart('/').Replace("{link}", "plc", StringComparison.Ordinal)))
            .Distinct();

    /// <summary>Whether a frame the PLC received is a command whose effect, by its row in the command table, is read-only, or the registration of a compound read.</summary>
    private static bool IsRead(string frame)
    {
        if (frame.Length == 0 || !frame.StartsWith('@'))
        {
            return frame.Length == 0; // a bare CR asks for an answer's next frame
        }

        byte[] bytes = Encoding.ASCII.GetBytes(frame);
        CModeCommandRow? row = frame.Length >= 5 ? CModeCommandTable.Standard.Find(bytes.AsSpan(3, 2), bytes.AsSpan(5)) : null;
        // QQMR registers what QQIR then reads (the planner's compound reads): it sets no PLC memory.
        return row is { Effect: CommandEffect.ReadOnly } || ReferenceEquals(row, CompoundCommands.RegisterRow);
    }

    /// <summary>The local addresses of the TCP sockets listening on this machine (IPv4 and IPv6), as the kernel lists them.</summary>
    private static IEnumerable<string> ListeningSockets()
    {
        foreach (string file in new[] { "/proc/net/tcp", "/proc/net/tcp6" })
        {
            foreach (string line in File.ReadLines(file).Skip(1))
            {
                string[] fields = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
                if (fields.Length > 3 && fields[3] == "0A")
                {
                    yield return fields[1];
                }
            }
        }
    }
}
