using System.Diagnostics;
using System.Runtime.InteropServices;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// The real <c>hostlink</c> entry point as a separate operating-system process (<c>dotnet hostlink.dll …</c> from the
/// test's output folder), as a user runs it: its own runtime, its own open of the port, signals.
/// </summary>
internal sealed class HostlinkProcess : ProgramProcess
{
    private HostlinkProcess(ProcessStartInfo start)
        : base(start)
    {
    }

    public static HostlinkProcess Start(params string[] args)
    {
        string dll = Path.Combine(AppContext.BaseDirectory, "hostlink.dll");
        File.Exists(dll).Should().BeTrue("the test project references the console project, so its output holds hostlink.dll");
        AllowSigIntInChildren();
        var process = new HostlinkProcess(DotnetStart(dll, Cli.WithAllowance(args)));
        process.Launch();
        return process;
    }

    /// <summary>Runs one command to its end.</summary>
    public static async Task<CliResult> RunAsync(TimeSpan timeout, params string[] args)
    {
        await using HostlinkProcess p = Start(args);
        int exit = await p.WaitForExitAsync(timeout)
            ?? throw new Xunit.Sdk.XunitException($"hostlink did not exit within {timeout.TotalSeconds} s.\nstdout:\n{p.Out}\nstderr:\n{p.Err}");
        return new CliResult(exit, p.Out, p.Err);
    }

    /// <summary>Waits until stdout (or stderr) holds <paramref name="text"/>; fails the test if hostlink exits first or takes longer than <paramref name="timeout"/>.</summary>
    public async Task ExpectOutputAsync(string text, TimeSpan timeout, bool onStandardError = false)
    {
        if (!await WaitUntilAsync(() => (onStandardError ? Err : Out).Contains(text, StringComparison.Ordinal), timeout))
        {
            throw new Xunit.Sdk.XunitException($"hostlink did not print '{text}' within {timeout.TotalSeconds} s (exited: {HasExited}).\nstdout:\n{Out}\nstderr:\n{Err}");
        }
    }

    /// <summary>
    /// A test host started in the background inherits SIGINT ignored, and so would every program it starts (an ignored
    /// signal stays ignored across exec). Ctrl+C is tested here, so children get the default disposition back.
    /// </summary>
    private static void AllowSigIntInChildren()
    {
        string status = File.ReadAllText("/proc/self/status");
        string line = status.Split('\n').First(l => l.StartsWith("SigIgn:", StringComparison.Ordinal));
        ulong ignored = Convert.ToUInt64(line["SigIgn:".Length..].Trim(), 16);
        if ((ignored & (1UL << (SigInt - 1))) != 0)
        {
            SetSignal(SigInt, IntPtr.Zero);
        }
    }

    [DllImport("libc", EntryPoint = "signal")]
    private static extern IntPtr SetSignal(int signal, IntPtr handler);
}
