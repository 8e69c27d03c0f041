using System.Diagnostics;
using System.Text;

namespace OmronHostLink.Com.Tests;

/// <summary>
/// The Windows test bed: a Wine prefix with the Windows .NET runtime (build/wine-bed.sh) and the artifacts a plant
/// installs (build/package.sh), both prepared here when they are missing or older than the sources, then the COM
/// server unzipped into the prefix and registered with its own register.cmd, as an administrator would. Nothing is
/// skipped for want of Wine: a bed that cannot be prepared fails every test that needs it, with the script's output.
/// The x86 (32-bit) bed depends on Debian's wine32 installing; where it does not, <see cref="X86Status"/> says why and
/// the x86 tests are reported as skipped with that reason.
/// </summary>
public sealed class WineBed : IAsyncLifetime
{
    private static readonly TimeSpan PrepareTimeout = TimeSpan.FromMinutes(30);
    private readonly Dictionary<string, string> _env = new(StringComparer.Ordinal);

    /// <summary>The repository's root: where OmronHostLink.sln is.</summary>
    public static string Root { get; } = FindRoot();

    public string Artifacts => Path.Combine(Root, "artifacts");

    public string Prefix => _env["WINEPREFIX"];

    /// <summary>Wine's 64-bit loader: runs 64-bit Windows programs, and Wine's own programs (cscript, regsvr32) as 64-bit.</summary>
    public string Wine64 => _env["WINE64"];

    /// <summary>Wine's 32-bit loader (Wine's own programs as 32-bit ones), or null without wine32.</summary>
    public string? Wine32 => _env["WINE32"] is { Length: > 0 } wine ? wine : null;

    /// <summary><c>ok</c>, or why there is no 32-bit Wine.</summary>
    public string X86Status => _env["X86_STATUS"];

    public string WineVersion => _env["WINE_VERSION"];

    /// <summary>The test tools compiled by the bed (scripthost-x64.exe, tlbcheck-x86.exe, …).</summary>
    public string Tools => _env["TOOLS"];

    /// <summary>Where the COM server's zip is unzipped, as Linux sees it: drive C:\OmronHostLink.Com.</summary>
    public string ComFolder => Path.Combine(Prefix, "drive_c", "OmronHostLink.Com");

    /// <summary>What register.cmd printed.</summary>
    public string RegistrationOutput { get; private set; } = "";

    public async Task InitializeAsync()
    {
        await Script("build/wine-bed.sh");
        if ((await Bash("build/package.sh --check", TimeSpan.FromMinutes(1))).ExitCode != 0)
        {
            await Script("build/package.sh");
        }

        foreach (string line in await File.ReadAllLinesAsync(Path.Combine(Artifacts, "wine", "bed.env")))
        {
            int equals = line.IndexOf('=', StringComparison.Ordinal);
            if (equals > 0)
            {
                _env[line[..equals]] = line[(equals + 1)..];
            }
        }

        // One wineserver for the whole run, instead of one started and stopped around every program.
        // A server of an earlier run that was stopped half-way is ended first. The new one detaches itself: its output
        // goes nowhere, so no pipe of ours is held open by it.
        ProcessResult server = await RunAsync("bash", ["-c", "wineserver -k 2>/dev/null; wineserver -p </dev/null >/dev/null 2>&1"], TimeSpan.FromMinutes(1));
        server.ExitCode.Should().Be(0, server.Output);

        if (Directory.Exists(ComFolder))
        {
            Directory.Delete(ComFolder, recursive: true);
        }

        System.IO.Compression.ZipFile.ExtractToDirectory(Artifact("OmronHostLink.Com-*-win.zip"), ComFolder);
        ProcessResult registration = await RunAsync(Wine64, ["cmd", "/c", @"C:\OmronHostLink.Com\register.cmd"], TimeSpan.FromMinutes(2));
        RegistrationOutput = registration.Output;
        registration.ExitCode.Should().Be(0, "register.cmd registers the server: " + registration.Output);
    }

    public async Task DisposeAsync()
    {
        if (_env.ContainsKey("WINEPREFIX"))
        {
            await RunAsync("wineserver", ["-k"], TimeSpan.FromMinutes(1));
        }
    }

    /// <summary>The one artifact matching <paramref name="pattern"/> in artifacts/.</summary>
    public string Artifact(string pattern)
    {
        string[] found = Directory.GetFiles(Artifacts, pattern);
        found.Should().ContainSingle($"build/package.sh makes one {pattern} in {Artifacts}");
        return found[0];
    }

    /// <summary>The loader for <paramref name="architecture"/> (<c>x64</c> or <c>x86</c>).</summary>
    public string WineFor(string architecture)
        => architecture == "x64" ? Wine64 : Wine32 ?? throw new InvalidOperationException("No 32-bit Wine: " + X86Status);

    /// <summary>A Linux path as Wine's programs see it (drive Z: is /).</summary>
    public static string WindowsPath(string path) => "Z:" + Path.GetFullPath(path).Replace('/', '\\');

    /// <summary>Runs a program with the bed's prefix, waiting for its exit; the output is standard output, then standard error.</summary>
    public Task<ProcessResult> RunAsync(string program, IEnumerable<string> arguments, TimeSpan timeout, IDictionary<string, string>? environment = null, string? workingDirectory = null)
    {
        ProcessStartInfo start = Start(program, arguments, environment, workingDirectory);
        return ProcessResult.RunAsync(start, timeout);
    }

    /// <summary>Starts a program with the bed's prefix and returns it running, its output read as it comes.</summary>
    public WineProcess Launch(string program, IEnumerable<string> arguments, IDictionary<string, string>? environment = null, string? workingDirectory = null)
        => new(Start(program, arguments, environment, workingDirectory));

    private ProcessStartInfo Start(string program, IEnumerable<string> arguments, IDictionary<string, string>? environment, string? workingDirectory)
    {
        var start = new ProcessStartInfo(program) { WorkingDirectory = workingDirectory ?? Root };
        foreach (string argument in arguments)
        {
            start.ArgumentList.Add(argument);
        }

        // The test host's .NET variables (DOTNET_ROOT and the like) name Linux paths; the Windows runtime in the prefix
        // must find its own installation, as it does on Windows.
        foreach (string name in start.Environment.Keys.Where(k => k.StartsWith("DOTNET_", StringComparison.Ordinal) || k.StartsWith("COREHOST_", StringComparison.Ordinal) || k.StartsWith("MSBUILD", StringComparison.OrdinalIgnoreCase)).ToList())
        {
            start.Environment.Remove(name);
        }

        start.Environment["WINEPREFIX"] = Prefix;
        start.Environment["WINEDEBUG"] = "-all";
        foreach ((string name, string value) in environment ?? new Dictionary<string, string>())
        {
            start.Environment[name] = value;
        }

        return start;
    }

    private static async Task Script(string script)
    {
        ProcessResult result = await Bash(script, PrepareTimeout);
        result.ExitCode.Should().Be(0, $"bash {script} prepares the Windows test bed; it said:\n{result.Output}");
    }

    private static Task<ProcessResult> Bash(string commandLine, TimeSpan timeout)
    {
        var start = new ProcessStartInfo("bash") { WorkingDirectory = Root };
        foreach (string part in commandLine.Split(' '))
        {
            start.ArgumentList.Add(part);
        }

        return ProcessResult.RunAsync(start, timeout);
    }

    private static string FindRoot()
    {
        for (DirectoryInfo? directory = new(AppContext.BaseDirectory); directory is not null; directory = directory.Parent)
        {
            if (File.Exists(Path.Combine(directory.FullName, "OmronHostLink.sln")))
            {
                return directory.FullName;
            }
        }

        throw new InvalidOperationException("OmronHostLink.sln not found above " + AppContext.BaseDirectory);
    }
}

/// <summary>
/// Where a program's output goes: files, not pipes. A Wine program can leave a process behind that inherits its
/// standard handles (winedevice.exe, started by the wineserver on first use of a device), so a pipe would never reach
/// its end and a reader waiting for it would wait forever; a file holds what was written once the program has exited.
/// </summary>
internal sealed class OutputFiles : IDisposable
{
    private readonly string _directory = Directory.CreateTempSubdirectory("omronhostlink-wine-").FullName;

    public string StandardOutput => Path.Combine(_directory, "out");

    public string StandardError => Path.Combine(_directory, "err");

    /// <summary>Runs <paramref name="start"/> through sh, its output into the files; returns the started process.</summary>
    public Process Start(ProcessStartInfo start)
    {
        var shell = new ProcessStartInfo("/bin/sh") { WorkingDirectory = start.WorkingDirectory, UseShellExecute = false };
        shell.Environment.Clear();
        foreach ((string name, string? value) in start.Environment)
        {
            shell.Environment[name] = value;
        }

        shell.ArgumentList.Add("-c");
        shell.ArgumentList.Add("exec \"$0\" \"$@\" </dev/null >\"$OMRONHOSTLINK_OUT\" 2>\"$OMRONHOSTLINK_ERR\"");
        shell.ArgumentList.Add(start.FileName);
        foreach (string argument in start.ArgumentList)
        {
            shell.ArgumentList.Add(argument);
        }

        shell.Environment["OMRONHOSTLINK_OUT"] = StandardOutput;
        shell.Environment["OMRONHOSTLINK_ERR"] = StandardError;
        return Process.Start(shell)!;
    }

    public string Read(string path)
    {
        try
        {
            using var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);
            using var reader = new StreamReader(stream);
            return reader.ReadToEnd();
        }
        catch (FileNotFoundException)
        {
            return "";
        }
    }

    public void Dispose() => Directory.Delete(_directory, recursive: true);
}

/// <summary>A finished program: its exit code and what it wrote.</summary>
public sealed record ProcessResult(int ExitCode, string StandardOutput, string StandardError)
{
    public string Output => StandardOutput + StandardError;

    /// <summary>Standard output's lines, without carriage returns.</summary>
    public string[] Lines => StandardOutput.Replace("\r", "", StringComparison.Ordinal).Split('\n', StringSplitOptions.RemoveEmptyEntries);

    /// <summary>The value of the first <c>name=value</c> line of standard output.</summary>
    public string Value(string name)
    {
        string? line = Lines.FirstOrDefault(l => l.StartsWith(name + "=", StringComparison.Ordinal));
        line.Should().NotBeNull($"the output has a line {name}=…:\n{Output}");
        return line![(name.Length + 1)..];
    }

    public static async Task<ProcessResult> RunAsync(ProcessStartInfo start, TimeSpan timeout)
    {
        using var files = new OutputFiles();
        using Process process = files.Start(start);
        using var cancel = new CancellationTokenSource(timeout);
        try
        {
            await process.WaitForExitAsync(cancel.Token);
        }
        catch (OperationCanceledException)
        {
            process.Kill(entireProcessTree: true);
            await process.WaitForExitAsync();
            throw new TimeoutException($"{start.FileName} {string.Join(' ', start.ArgumentList)} did not finish in {timeout}:\n{files.Read(files.StandardOutput)}{files.Read(files.StandardError)}");
        }

        return new ProcessResult(process.ExitCode, files.Read(files.StandardOutput), files.Read(files.StandardError));
    }
}

/// <summary>A running program under Wine whose output lines a test waits for, as they reach its output file.</summary>
public sealed class WineProcess : IAsyncDisposable
{
    private readonly OutputFiles _files = new();
    private readonly Process _process;
    private readonly FileSystemWatcher _watcher;
    private readonly SemaphoreSlim _changed = new(0);

    public WineProcess(ProcessStartInfo start)
    {
        _watcher = new FileSystemWatcher(Path.GetDirectoryName(_files.StandardOutput)!) { NotifyFilter = NotifyFilters.Size | NotifyFilters.LastWrite | NotifyFilters.FileName };
        _watcher.Changed += (_, _) => _changed.Release();
        _watcher.Created += (_, _) => _changed.Release();
        _watcher.EnableRaisingEvents = true;
        _process = _files.Start(start);
        _process.EnableRaisingEvents = true;
        _process.Exited += (_, _) => _changed.Release();
    }

    public IReadOnlyList<string> Lines
        => _files.Read(_files.StandardOutput).Replace("\r", "", StringComparison.Ordinal).Split('\n', StringSplitOptions.RemoveEmptyEntries);

    public string Output => _files.Read(_files.StandardOutput) + _files.Read(_files.StandardError);

    public bool HasExited => _process.HasExited;

    public int ExitCode => _process.ExitCode;

    /// <summary>Waits for a line that <paramref name="match"/> accepts; fails with the output so far after <paramref name="timeout"/>.</summary>
    public async Task<string> WaitForLineAsync(Func<string, bool> match, TimeSpan timeout, string what)
    {
        using var cancel = new CancellationTokenSource(timeout);
        while (true)
        {
            string? found = Lines.FirstOrDefault(match);
            if (found is not null)
            {
                return found;
            }

            if (_process.HasExited)
            {
                throw new InvalidOperationException($"The program exited ({_process.ExitCode}) without a line {what}:\n{Output}");
            }

            try
            {
                await _changed.WaitAsync(cancel.Token);
            }
            catch (OperationCanceledException)
            {
                throw new TimeoutException($"No line {what} in {timeout}:\n{Output}");
            }
        }
    }

    public async Task<int> WaitForExitAsync(TimeSpan timeout)
    {
        using var cancel = new CancellationTokenSource(timeout);
        try
        {
            await _process.WaitForExitAsync(cancel.Token);
        }
        catch (OperationCanceledException)
        {
            throw new TimeoutException($"{_process.StartInfo.ArgumentList.ElementAtOrDefault(2)} did not exit in {timeout}:\n{Output}");
        }

        return _process.ExitCode;
    }

    public async ValueTask DisposeAsync()
    {
        if (!_process.HasExited)
        {
            _process.Kill(entireProcessTree: true);
            await _process.WaitForExitAsync();
        }

        _watcher.Dispose();
        _process.Dispose();
        _changed.Dispose();
        _files.Dispose();
    }
}

[CollectionDefinition(Name)]
public sealed class WineCollection : ICollectionFixture<WineBed>
{
    public const string Name = "Wine";
}
