namespace OmronHostLink.Cli;

/// <summary>
/// <c>simulate --ready-file</c>: a file that exists exactly while the simulator accepts connections, holding the address
/// it serves, so a script can start it in the background and wait for the file instead of guessing a delay.
/// </summary>
internal static class ReadyFile
{
    /// <summary>Writes <paramref name="content"/> to <paramref name="path"/> at once (written aside, then moved), when a path is given.</summary>
    public static void Write(string? path, string content)
    {
        if (path is null)
        {
            return;
        }

        string full = Path.GetFullPath(path);
        string temporary = full + ".tmp-" + Environment.ProcessId;
        try
        {
            File.WriteAllText(temporary, content + Environment.NewLine);
            File.Move(temporary, full, overwrite: true);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            File.Delete(temporary);
            throw new UsageException($"--ready-file: cannot write {full}: {e.Message}", e);
        }
    }

    /// <summary>Removes the file if it is there.</summary>
    public static void Remove(string path)
    {
        try
        {
            File.Delete(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"--ready-file: cannot remove {Path.GetFullPath(path)}: {e.Message}", e);
        }
    }
}
