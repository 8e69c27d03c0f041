using System.Diagnostics;
using System.Text.Json;
using System.Text.Json.Nodes;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>
/// Eclipse Tahu's JavaScript payload library (npm <c>sparkplug-payload</c>) in a node process: the independent
/// implementation that decodes what the gateway publishes and encodes the commands a host application sends.
/// <c>./build.sh prepare</c> (which <c>./build.sh test</c> and CI run) installs node and runs <c>npm ci</c> in <c>Sparkplug/Tahu</c>.
/// </summary>
public sealed class TahuCodec : IDisposable
{
    private readonly Process _node;
    private readonly SemaphoreSlim _gate = new(1, 1);

    public TahuCodec()
    {
        string folder = Folder();
        string node = MosquittoBroker.Find("node", "/usr/bin/node", "/usr/local/bin/node")
            ?? throw new InvalidOperationException("node is not installed; the Sparkplug tests decode with Eclipse Tahu's JavaScript library. Install it (Debian: apt-get install nodejs npm) and run npm ci in " + folder + ".");
        if (!Directory.Exists(Path.Combine(folder, "node_modules", "sparkplug-payload")))
        {
            throw new InvalidOperationException($"sparkplug-payload is not installed: run 'npm ci' in {folder} (./build.sh prepare does).");
        }

        var start = new ProcessStartInfo(node, "codec.js")
        {
            WorkingDirectory = folder,
            RedirectStandardInput = true,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        _node = Process.Start(start)!;
    }

    /// <summary>Decodes a payload as Tahu reads it; 64-bit numbers come back as decimal strings.</summary>
    public async Task<JsonObject> DecodeAsync(byte[] payload)
        => (JsonObject)(await AskAsync("decode " + Convert.ToBase64String(payload)))!;

    /// <summary>Encodes a payload given in Tahu's JSON form (metrics with name, type, value…).</summary>
    public async Task<byte[]> EncodeAsync(object payload)
        => Convert.FromBase64String((await AskAsync("encode " + JsonSerializer.Serialize(payload)))!.GetValue<string>());

    private async Task<JsonNode?> AskAsync(string line)
    {
        await _gate.WaitAsync();
        try
        {
            await _node.StandardInput.WriteLineAsync(line);
            await _node.StandardInput.FlushAsync();
            using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(20));
            string? answer = await _node.StandardOutput.ReadLineAsync(timeout.Token)
                ?? throw new InvalidOperationException("node ended: " + await _node.StandardError.ReadToEndAsync());
            JsonObject reply = JsonNode.Parse(answer)!.AsObject();
            return reply["error"] is { } error ? throw new InvalidOperationException("Tahu: " + error) : reply["ok"];
        }
        finally
        {
            _gate.Release();
        }
    }

    private static string Folder()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            string candidate = Path.Combine(dir.FullName, "Sparkplug", "Tahu");
            if (File.Exists(Path.Combine(candidate, "codec.js")))
            {
                return candidate;
            }
        }

        throw new InvalidOperationException("Sparkplug/Tahu/codec.js not found above " + AppContext.BaseDirectory);
    }

    public void Dispose()
    {
        try
        {
            _node.StandardInput.Close();
            if (!_node.WaitForExit(2000))
            {
                _node.Kill();
            }
        }
        catch (InvalidOperationException)
        {
        }

        _node.Dispose();
        _gate.Dispose();
    }
}
