using System.Diagnostics;
using System.Text;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// The real <c>hostlink</c> entry point as a separate operating-system process (<c>dotnet hostlink.dll …</c> from the
/// test's output folder), as a user runs it: its own runtime, its own open of the port.
/// </summary>
internal sealed class HostlinkProcess : IAsyncDisposable
{
    private readonly Process _process;
    private readonly StringBuilder _out = new();
    private readonly StringBuilder _err = new();

    private HostlinkProcess(Process process)
    {
        _process = process;
    }

    public int Id => _process.Id;

    public string Out
    {
        get
        {
            lock (_out)
            {
                return _out.ToString();
            }
        }
    }

    public string Err
    {
        get
        {
            lock (_err)
            {
                return _err.ToString();
            }
        }
    }

    public static HostlinkProcess Start(params string[] args)
    {
        string dll = Path.Combine(AppContext.BaseDirectory, "hostlink.dll");
        File.Exists(dll).Should().BeTrue("the test project references the console project, so its output holds hostlink.dll");
        string? host = Environment.ProcessPath;
        var start = new ProcessStartInfo(host is not null && Path.GetFileNameWithoutExtension(host) == "dotnet" ? host : "dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        start.ArgumentList.Add(dll);
        foreach (string a in Cli.WithAllowance(args))
        {
            start.ArgumentList.Add(a);
        }

        var process = new Process { StartInfo = start };
        var result = new HostlinkProcess(process);
        process.OutputDataReceived += (_, e) => Append(result._out, e.Data);
        process.ErrorDataReceived += (_, e) => Append(result._err, e.Data);
        process.Start();
        process.BeginOutputReadLine();
        process.BeginErrorReadLine();
        return result;
    }

    /// <summary>Runs one command to its end.</summary>
    public static async Task<CliResult> RunAsync(TimeSpan timeout, params string[] args)
    {
        await using HostlinkProcess p = Start(args);
        int exit = await p.WaitForExitAsync(timeout);
        return new CliResult(exit, p.Out, p.Err);
    }

    /// <summary>Waits until stdout (or stderr) holds <paramref name="text"/>.</summary>
    public async Task WaitForOutputAsync(string text, TimeSpan timeout, bool onStandardError = false)
    {
        var clock = Stopwatch.StartNew();
        while (!(onStandardError ? Err : Out).Contains(text, StringComparison.Ordinal))
        {
            if (_process.HasExited || clock.Elapsed > timeout)
            {
                throw new Xunit.Sdk.XunitException($"hostlink did not print '{text}' within {timeout.TotalSeconds} s (exited: {_process.HasExited}).\nstdout:\n{Out}\nstderr:\n{Err}");
            }

            await Task.Delay(20);
        }
    }

    public async Task<int> WaitForExitAsync(TimeSpan timeout)
    {
        using var cts = new CancellationTokenSource(timeout);
        try
        {
            await _process.WaitForExitAsync(cts.Token);
        }
        catch (OperationCanceledException)
        {
            throw new Xunit.Sdk.XunitException($"hostlink did not exit within {timeout.TotalSeconds} s.\nstdout:\n{Out}\nstderr:\n{Err}");
        }

        _process.WaitForExit(); // drains the redirected output
        return _process.ExitCode;
    }

    /// <summary>Asks the process to stop as a service manager does (SIGTERM).</summary>
    public async Task TerminateAsync()
    {
        using Process kill = Process.Start("kill", ["-TERM", _process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]);
        await kill.WaitForExitAsync();
    }

    public async ValueTask DisposeAsync()
    {
        if (!_process.HasExited)
        {
            _process.Kill(entireProcessTree: true);
            await _process.WaitForExitAsync();
        }

        _process.Dispose();
    }

    private static void Append(StringBuilder to, string? line)
    {
        if (line is not null)
        {
            lock (to)
            {
                to.AppendLine(line);
            }
        }
    }
}
