using System.Diagnostics;
using System.Runtime.InteropServices;
using System.Text;

namespace OmronHostLink.Testing;

/// <summary>
/// A built program run as its own operating-system process, as a user or a service manager runs it, with what it
/// writes to standard output and standard error read line by line as it comes. A test waits for a line, signals the
/// process, waits for its exit and reads what it wrote. Disposing it kills what is still running (with the processes
/// it started) and deletes the directory it was given to own.
/// </summary>
/// <remarks>
/// A launcher derives from this: it builds the start (<see cref="DotnetStart"/> for a .NET program), calls
/// <see cref="Launch"/> and adds only what is its own (where the program is, its configuration, what its lines mean).
/// </remarks>
public class ProgramProcess : IAsyncDisposable
{
    /// <summary>SIGINT, what Ctrl+C sends.</summary>
    public const int SigInt = 2;

    /// <summary>SIGKILL: the process ends at once, none of its own code runs.</summary>
    public const int SigKill = 9;

    /// <summary>SIGTERM, what a service manager sends to stop a service.</summary>
    public const int SigTerm = 15;


    private readonly Process _process;
    private readonly Queue<(string Text, bool FromStandardError)> _lines = new();
    private readonly int _keepLines;
    private readonly string? _ownedDirectory;
    private bool _launched;
    private bool _disposed;

    /// <summary>Prepares <paramref name="start"/> (output and error redirected, no shell); <see cref="Launch"/> starts it.</summary>
    /// <param name="start">The program, its arguments, environment and working directory.</param>
    /// <param name="ownedDirectory">A directory made for the process (its working directory), deleted on dispose; or null.</param>
    /// <param name="keepLines">
    /// How many of the latest lines to keep; null keeps them all. A long run of a program that logs much keeps a bounded tail.
    /// </param>
    protected ProgramProcess(ProcessStartInfo start, string? ownedDirectory = null, int? keepLines = null)
    {
        ArgumentNullException.ThrowIfNull(start);
        start.UseShellExecute = false;
        start.RedirectStandardOutput = true;
        start.RedirectStandardError = true;
        _process = new Process { StartInfo = start };
        _process.OutputDataReceived += (_, e) => Add(e.Data, fromStandardError: false);
        _process.ErrorDataReceived += (_, e) => Add(e.Data, fromStandardError: true);
        _ownedDirectory = ownedDirectory;
        _keepLines = keepLines ?? int.MaxValue;
    }

    /// <summary>
    /// The <c>dotnet</c> host that runs this process (so a program started with it runs on the same runtime), found as
    /// the running host, else beside the running runtime, else on the PATH.
    /// </summary>
    public static string DotnetHost { get; } = FindDotnetHost();

    /// <summary>The process id.</summary>
    public int Id => _process.Id;

    /// <summary>Whether the process has exited.</summary>
    public bool HasExited => _process.HasExited;

    /// <summary>The exit code, once it has exited.</summary>
    public int ExitCode => _process.ExitCode;

    /// <summary>The process itself, for what a launcher of its own does with it.</summary>
    protected Process Process => _process;

    /// <summary>The lines kept so far, standard output and standard error together, in the order they came.</summary>
    public IReadOnlyList<string> Lines
    {
        get
        {
            lock (_lines)
            {
                return _lines.Select(l => l.Text).ToArray();
            }
        }
    }

    /// <summary>The lines kept so far, standard output and standard error together, each ended by a newline.</summary>
    public string Output => Text(_ => true);

    /// <summary>What the program has written to standard output, each line ended by a newline.</summary>
    public string Out => Text(l => !l.FromStandardError);

    /// <summary>What the program has written to standard error, each line ended by a newline.</summary>
    public string Err => Text(l => l.FromStandardError);

    /// <summary><c>dotnet <paramref name="assembly"/> <paramref name="arguments"/></c>, on <see cref="DotnetHost"/>.</summary>
    public static ProcessStartInfo DotnetStart(string assembly, IEnumerable<string> arguments)
    {
        ArgumentNullException.ThrowIfNull(arguments);
        var start = new ProcessStartInfo(DotnetHost);
        start.ArgumentList.Add(assembly);
        foreach (string argument in arguments)
        {
            start.ArgumentList.Add(argument);
        }

        return start;
    }

    /// <summary>A new empty directory in the temp directory (a working directory with no appsettings.json in it).</summary>
    public static string NewDirectory(string prefix) => Directory.CreateTempSubdirectory(prefix).FullName;

    /// <summary>Sends <paramref name="signal"/> to process <paramref name="processId"/>; one that has exited already is no error.</summary>
    /// <exception cref="InvalidOperationException">The signal could not be sent.</exception>
    public static void SendSignal(int processId, int signal)
    {
        const int NoSuchProcess = 3; // ESRCH
        if (Kill(processId, signal) != 0 && Marshal.GetLastPInvokeError() is var error && error != NoSuchProcess)
        {
            throw new InvalidOperationException($"kill({processId}, {signal}) failed: errno {error}");
        }
    }

    /// <summary>Sends <paramref name="signal"/> (<see cref="SigTerm"/>, <see cref="SigInt"/>…) to the program.</summary>
    public virtual void Signal(int signal) => SendSignal(Id, signal);

    /// <summary>The first line (of either stream) that satisfies <paramref name="match"/>; null if none has after <paramref name="timeout"/> or when the process has exited.</summary>
    public async Task<string?> WaitForLineAsync(Func<string, bool> match, TimeSpan timeout)
    {
        string? line = null;
        await WaitUntilAsync(() => (line = Lines.FirstOrDefault(match)) is not null, timeout).ConfigureAwait(false);
        return line;
    }

    /// <summary>Whether the output (either stream) holds <paramref name="text"/>: false after <paramref name="timeout"/> or when the process has exited without it.</summary>
    public async Task<bool> WaitForOutputAsync(string text, TimeSpan timeout)
        => await WaitForLineAsync(l => l.Contains(text, StringComparison.Ordinal), timeout).ConfigureAwait(false) is not null;

    /// <summary>The exit code, with all the output read; null if the process is still running after <paramref name="timeout"/>.</summary>
    public async Task<int?> WaitForExitAsync(TimeSpan timeout)
    {
        using var cts = new CancellationTokenSource(timeout);
        try
        {
            // Completes once the process has exited and its redirected output has been read to the end.
            await _process.WaitForExitAsync(cts.Token).ConfigureAwait(false);
            return _process.ExitCode;
        }
        catch (OperationCanceledException)
        {
            return null;
        }
    }

    /// <summary>Kills the process at once (SIGKILL: none of its shutdown code runs) and waits until it is gone.</summary>
    public async Task KillAsync()
    {
        _process.Kill();
        await _process.WaitForExitAsync().ConfigureAwait(false);
    }

    /// <summary>
    /// Stops the program as a service manager does: SIGTERM, then, if it is still running after <paramref name="patience"/>,
    /// kills it with the processes it started.
    /// </summary>
    /// <returns>Whether it stopped by itself.</returns>
    public async Task<bool> StopAsync(TimeSpan patience)
    {
        if (!_launched || _disposed || _process.HasExited)
        {
            return true;
        }

        Signal(SigTerm);
        if (await WaitForExitAsync(patience).ConfigureAwait(false) is not null)
        {
            return true;
        }

        _process.Kill(entireProcessTree: true);
        await _process.WaitForExitAsync().WaitAsync(TimeSpan.FromSeconds(5)).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        return false;
    }

    /// <summary>The process, its state and its output, for a failure message.</summary>
    public override string ToString()
    {
        string state = !_launched ? "not started" : _disposed ? "disposed" : _process.HasExited ? $"exited with {_process.ExitCode}" : $"running as {_process.Id}";
        return $"{Path.GetFileName(_process.StartInfo.FileName)} {state}; output:{Environment.NewLine}{Output}";
    }

    public async ValueTask DisposeAsync()
    {
        await DisposeAsyncCore().ConfigureAwait(false);
        GC.SuppressFinalize(this);
    }

    /// <summary>Kills the process (with the processes it started) if it still runs, then deletes the owned directory.</summary>
    protected virtual async ValueTask DisposeAsyncCore()
    {
        if (_disposed)
        {
            return;
        }

        _disposed = true;
        if (_launched && !_process.HasExited)
        {
            _process.Kill(entireProcessTree: true);
            await _process.WaitForExitAsync().ConfigureAwait(false);
        }

        _process.Dispose();
        if (_ownedDirectory is not null)
        {
            try
            {
                Directory.Delete(_ownedDirectory, recursive: true);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // Left in the temp directory.
            }
        }
    }

    /// <summary>Starts the process and the reading of its output.</summary>
    protected void Launch()
    {
        _process.Start();
        _launched = true;
        _process.BeginOutputReadLine();
        _process.BeginErrorReadLine();
    }

    /// <summary>Polls <paramref name="condition"/> until it holds, <paramref name="timeout"/> has passed or the process has exited (then with all its output read).</summary>
    /// <returns>Whether it holds.</returns>
    protected async Task<bool> WaitUntilAsync(Func<bool> condition, TimeSpan timeout)
    {
        ArgumentNullException.ThrowIfNull(condition);
        try
        {
            await Eventually.UntilAsync(() => condition() || _process.HasExited, "the program prints it or exits", patience: timeout).ConfigureAwait(false);
        }
        catch (TimeoutException)
        {
            return false;
        }

        if (!condition() && _process.HasExited)
        {
            await WaitForExitAsync(TimeSpan.FromSeconds(5)).ConfigureAwait(false);
        }

        return condition();
    }

    /// <summary>Called with each line as it comes (on a thread of the output reader, for either stream).</summary>
    protected virtual void OnLine(string line)
    {
    }

    private void Add(string? line, bool fromStandardError)
    {
        if (line is null)
        {
            return;
        }

        lock (_lines)
        {
            if (_lines.Count == _keepLines)
            {
                _lines.Dequeue();
            }

            _lines.Enqueue((line, fromStandardError));
        }

        OnLine(line);
    }

    private string Text(Func<(string Text, bool FromStandardError), bool> which)
    {
        var text = new StringBuilder();
        lock (_lines)
        {
            foreach ((string Text, bool FromStandardError) line in _lines.Where(which))
            {
                text.AppendLine(line.Text);
            }
        }

        return text.ToString();
    }

    private static string FindDotnetHost()
    {
        string? current = Environment.ProcessPath;
        if (current is not null && Path.GetFileNameWithoutExtension(current) == "dotnet")
        {
            return current;
        }

        // <root>/shared/Microsoft.NETCore.App/<version>/ → <root>/dotnet
        string beside = Path.GetFullPath(Path.Combine(RuntimeEnvironment.GetRuntimeDirectory(), "..", "..", "..", "dotnet"));
        return File.Exists(beside) ? beside : "dotnet";
    }

    [DllImport("libc", EntryPoint = "kill", SetLastError = true)]
    private static extern int Kill(int pid, int signal);
}
