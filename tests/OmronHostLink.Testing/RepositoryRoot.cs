namespace OmronHostLink.Testing;

/// <summary>
/// The repository's root folder (the one holding <c>OmronHostLink.sln</c>), found above the test assembly. Tests read
/// sources and docs from it; a <c>[CallerFilePath]</c> would not do, because CI builds map source paths to <c>/_/</c>.
/// </summary>
public static class RepositoryRoot
{
    private static readonly Lazy<string> Found = new(Find);

    /// <summary>The root folder's full path.</summary>
    public static string Path => Found.Value;

    /// <summary>A path under the root, from its parts.</summary>
    public static string Combine(params string[] parts) => System.IO.Path.Combine([Path, .. parts]);

    private static string Find()
    {
        for (DirectoryInfo? d = new(AppContext.BaseDirectory); d is not null; d = d.Parent)
        {
            if (File.Exists(System.IO.Path.Combine(d.FullName, "OmronHostLink.sln")))
            {
                return d.FullName;
            }
        }

        throw new InvalidOperationException("The repository root (OmronHostLink.sln) is not above " + AppContext.BaseDirectory);
    }
}
