using System.ComponentModel;
using System.Diagnostics;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// tshark (Debian package tshark) with the repository's Host Link dissector: the fields of each frame of a capture.
/// The tests that use it fail rather than skip without it, so CI cannot silently lose them.
/// </summary>
internal static class Tshark
{
    /// <summary>The dissector the repository ships, in tools/wireshark.</summary>
    public static string Dissector => RepositoryRoot.Combine("tools", "wireshark", "omron-hostlink.lua");

    /// <summary>Runs tshark over <paramref name="capture"/> and returns one row a frame, one cell a field (its first occurrence).</summary>
    public static async Task<List<string[]>> FieldsAsync(string capture, params string[] fields)
    {
        var start = new ProcessStartInfo("tshark")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string argument in new[] { "-X", "lua_script:" + Dissector, "-r", capture, "-T", "fields", "-E", "separator=|", "-E", "occurrence=f" })
        {
            start.ArgumentList.Add(argument);
        }

        foreach (string field in fields)
        {
            start.ArgumentList.Add("-e");
            start.ArgumentList.Add(field);
        }

        using var process = new Process { StartInfo = start };
        try
        {
            process.Start();
        }
        catch (Win32Exception e)
        {
            throw new InvalidOperationException("tshark is not installed or not on PATH; the capture tests need it (Debian/Ubuntu: apt-get install tshark).", e);
        }

        Task<string> output = process.StandardOutput.ReadToEndAsync();
        Task<string> errors = process.StandardError.ReadToEndAsync();
        using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        await process.WaitForExitAsync(timeout.Token);
        string text = await output;
        process.ExitCode.Should().Be(0, "tshark reads the capture: {0}", await errors);
        (await errors).Should().NotContain("Lua: Error", "the dissector loads and runs without errors");
        return text.Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => l.TrimEnd('\r').Split('|')).ToList();
    }
}
