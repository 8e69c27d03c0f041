using System.Text;
using System.Text.RegularExpressions;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The gateway's folders point one way: each folder is one namespace, no folder depends on another that depends on it
/// (directly or through others), and none depends on the composition root (<c>GatewayHost</c>, <c>GatewayProgram</c>),
/// which depends on them all. Read from the sources: a folder depends on another when one of its files names that
/// namespace (a using directive, a qualified name, a documentation reference) or, for the root, one of its types.
/// </summary>
public sealed partial class GatewayArchitectureTests(ITestOutputHelper output)
{
    private const string RootNamespace = "OmronHostLink.Gateway";
    private const string Root = "(root)";

    [Fact]
    public void Each_folder_is_one_namespace()
    {
        foreach (SourceFile file in Sources())
        {
            string expected = file.Folder == Root ? RootNamespace : $"{RootNamespace}.{file.Folder}";
            file.Namespace.Should().Be(expected, "{0} lies in {1}", file.Path, file.Folder);
        }
    }

    [Fact]
    public void No_two_folders_depend_on_each_other_and_none_on_the_composition_root()
    {
        Dictionary<string, Dictionary<string, List<string>>> graph = Dependencies(Sources());
        output.WriteLine(Describe(graph));

        foreach ((string folder, Dictionary<string, List<string>> uses) in graph.Where(g => g.Key != Root))
        {
            uses.Should().NotContainKey(Root, "{0} must not depend on the composition root (by {1})", folder, uses.GetValueOrDefault(Root) is { } why ? string.Join(", ", why) : "");
        }

        foreach (string folder in graph.Keys)
        {
            foreach ((string other, List<string> why) in graph[folder])
            {
                List<string>? back = Path(graph, other, folder);
                back.Should().BeNull(
                    "{0} depends on {1} (by {2}) and {1} depends back on {0} through {3}",
                    folder,
                    other,
                    string.Join(", ", why),
                    back is null ? "" : string.Join(" -> ", back));
            }
        }
    }

    [Fact]
    public void The_application_makes_public_only_its_entry_points_and_the_seam_its_outputs_plug_into()
    {
        // Everything else is internal: the tests and benchmarks reach it through InternalsVisibleTo.
        typeof(GatewayHost).Assembly.GetExportedTypes().Select(t => t.FullName).Should().BeEquivalentTo(
        [
            "OmronHostLink.Gateway.GatewayHost",
            "OmronHostLink.Gateway.GatewayProgram",
            "OmronHostLink.Gateway.Outputs.ITagOutput",
            "OmronHostLink.Gateway.Outputs.TagChange",
            "OmronHostLink.Gateway.Outputs.TagQuality",
            "OmronHostLink.Gateway.Outputs.LinkState",
            "OmronHostLink.Gateway.Outputs.UnitState",
        ]);
    }

    [Fact]
    public void The_dependency_reader_sees_usings_qualified_names_documentation_and_root_types()
    {
        // The reader itself: it must find what a folder names, and nothing in comments or text.
        var files = new[]
        {
            new SourceFile("A/One.cs", "A", "OmronHostLink.Gateway.A", Code("using OmronHostLink.Gateway.B;\nnamespace OmronHostLink.Gateway.A;\nclass One { string s = \"C.Thing\"; // D.Thing\n}")),
            new SourceFile("B/Two.cs", "B", "OmronHostLink.Gateway.B", Code("namespace OmronHostLink.Gateway.B;\n/// <see cref=\"C.Thing\"/>\nclass Two { object x = D.Thing.Make($\"{E.Thing.Name}\"); }")),
            new SourceFile("C/Three.cs", "C", "OmronHostLink.Gateway.C", Code("namespace OmronHostLink.Gateway.C;\nclass Three { object h = GatewayHost.CreateBuilder; }")),
            new SourceFile("GatewayHost.cs", Root, RootNamespace, Code("namespace OmronHostLink.Gateway;\npublic static class GatewayHost { }")),
        };

        Dictionary<string, Dictionary<string, List<string>>> graph = Dependencies(files, ["A", "B", "C", "D", "E"]);

        graph["A"].Keys.Should().BeEquivalentTo(["B"]);
        graph["B"].Keys.Should().BeEquivalentTo(["C", "D", "E"]);
        graph["C"].Keys.Should().BeEquivalentTo([Root]);
    }

    /// <summary>A source file of the gateway: where it lies and its code without comments and text (documentation references kept).</summary>
    private sealed record SourceFile(string Path, string Folder, string Namespace, string Code);

    private static string GatewaySource() => RepositoryRoot.Combine("src", "OmronHostLink.Gateway");

    private static List<SourceFile> Sources()
    {
        string source = GatewaySource();
        var files = new List<SourceFile>();
        foreach (string path in Directory.EnumerateFiles(source, "*.cs", SearchOption.AllDirectories))
        {
            string relative = System.IO.Path.GetRelativePath(source, path).Replace('\\', '/');
            if (relative.StartsWith("obj/", StringComparison.Ordinal) || relative.StartsWith("bin/", StringComparison.Ordinal))
            {
                continue;
            }

            string text = File.ReadAllText(path);
            string folder = relative.Contains('/', StringComparison.Ordinal) ? relative.Substring(0, relative.IndexOf('/', StringComparison.Ordinal)) : Root;
            string ns = NamespaceDeclaration().Match(text) is { Success: true } m ? m.Groups[1].Value : RootNamespace;
            files.Add(new SourceFile(relative, folder, ns, Code(text)));
        }

        return files;
    }

    /// <summary>Each folder's dependencies on the others, with the files (and names) that make them.</summary>
    private static Dictionary<string, Dictionary<string, List<string>>> Dependencies(IReadOnlyList<SourceFile> files, IReadOnlyList<string>? folders = null)
    {
        folders ??= files.Select(f => f.Folder).Where(f => f != Root).Distinct().ToList();
        string[] rootTypes = files.Where(f => f.Folder == Root)
            .SelectMany(f => TopLevelType().Matches(f.Code).Select(m => m.Groups[1].Value))
            .ToArray();
        var graph = files.Select(f => f.Folder).Concat(folders).Distinct()
            .ToDictionary(f => f, _ => new Dictionary<string, List<string>>(StringComparer.Ordinal), StringComparer.Ordinal);
        foreach (SourceFile file in files)
        {
            void Add(string to, string name)
            {
                if (to == file.Folder || !graph.ContainsKey(to))
                {
                    return;
                }

                Dictionary<string, List<string>> uses = graph[file.Folder];
                if (!uses.TryGetValue(to, out List<string>? why))
                {
                    uses[to] = why = [];
                }

                string reason = $"{file.Path}: {name}";
                if (!why.Contains(reason))
                {
                    why.Add(reason);
                }
            }

            foreach (Match m in NamespaceName().Matches(file.Code))
            {
                Add(m.Groups[1].Value, m.Value);
            }

            foreach (string folder in folders)
            {
                foreach (Match m in Regex.Matches(file.Code, $@"(?<![\w.]){folder}\.[A-Z]\w*"))
                {
                    Add(folder, m.Value);
                }
            }

            if (file.Folder != Root)
            {
                foreach (string type in rootTypes)
                {
                    if (Regex.IsMatch(file.Code, $@"(?<![\w.]){type}\b"))
                    {
                        Add(Root, type);
                    }
                }
            }
        }

        return graph;
    }

    /// <summary>A path from <paramref name="from"/> to <paramref name="to"/> in the graph; null when there is none.</summary>
    private static List<string>? Path(Dictionary<string, Dictionary<string, List<string>>> graph, string from, string to)
    {
        var previous = new Dictionary<string, string> { [from] = "" };
        var queue = new Queue<string>([from]);
        while (queue.Count > 0)
        {
            string node = queue.Dequeue();
            if (node == to)
            {
                var path = new List<string>();
                for (string n = to; n.Length > 0; n = previous[n])
                {
                    path.Insert(0, n);
                }

                return path;
            }

            foreach (string next in graph.GetValueOrDefault(node)?.Keys ?? Enumerable.Empty<string>())
            {
                if (previous.TryAdd(next, node))
                {
                    queue.Enqueue(next);
                }
            }
        }

        return null;
    }

    private static string Describe(Dictionary<string, Dictionary<string, List<string>>> graph)
    {
        var text = new StringBuilder();
        foreach ((string folder, Dictionary<string, List<string>> uses) in graph.OrderBy(g => g.Key, StringComparer.Ordinal))
        {
            text.Append(folder).Append(" -> ").AppendLine(string.Join(", ", uses.Keys.Order(StringComparer.Ordinal)));
        }

        return text.ToString();
    }

    /// <summary>
    /// The code of a C# file without comments and without the contents of string and character literals (so that text
    /// naming a folder is no dependency), with its documentation's <c>cref</c> references appended (they are).
    /// </summary>
    private static string Code(string text)
    {
        var code = new StringBuilder(text.Length);
        int i = 0;
        Scan(stopAtBrace: false);
        foreach (Match m in CrefReference().Matches(text))
        {
            code.Append('\n').Append(m.Groups[1].Value);
        }

        return code.ToString();

        void Scan(bool stopAtBrace)
        {
            int depth = 0;
            while (i < text.Length)
            {
                char c = text[i];
                if (stopAtBrace && c == '{')
                {
                    depth++;
                }
                else if (stopAtBrace && c == '}' && depth-- == 0)
                {
                    i++;
                    return;
                }

                if (At("//"))
                {
                    int end = text.IndexOf('\n', i);
                    i = end < 0 ? text.Length : end;
                }
                else if (At("/*"))
                {
                    int end = text.IndexOf("*/", i + 2, StringComparison.Ordinal);
                    i = end < 0 ? text.Length : end + 2;
                }
                else if (c == '\'')
                {
                    // Past the opening quote and the first character (both of an escape), to the closing quote.
                    i += text[i + 1] == '\\' ? 3 : 2;
                    while (i < text.Length && text[i] != '\'')
                    {
                        i++;
                    }

                    i++;
                    code.Append(' ');
                }
                else if (At("$@\"") || At("@$\""))
                {
                    SkipString(i + 2, verbatim: true, interpolated: true);
                }
                else if (At("$\""))
                {
                    SkipString(i + 1, verbatim: false, interpolated: true);
                }
                else if (At("@\""))
                {
                    SkipString(i + 1, verbatim: true, interpolated: false);
                }
                else if (c == '"')
                {
                    SkipString(i, verbatim: false, interpolated: false);
                }
                else
                {
                    code.Append(c);
                    i++;
                }
            }
        }

        // From the opening quote at 'start' to past the closing one; an interpolation's holes are code.
        void SkipString(int start, bool verbatim, bool interpolated)
        {
            i = start + 1;
            code.Append("\"\"");
            while (i < text.Length)
            {
                char c = text[i];
                if (verbatim && c == '"' && i + 1 < text.Length && text[i + 1] == '"')
                {
                    i += 2;
                }
                else if (!verbatim && c == '\\')
                {
                    i += 2;
                }
                else if (c == '"')
                {
                    i++;
                    return;
                }
                else if (interpolated && c == '{' && i + 1 < text.Length && text[i + 1] == '{')
                {
                    i += 2;
                }
                else if (interpolated && c == '{')
                {
                    i++;
                    code.Append(' ');
                    Scan(stopAtBrace: true);
                    code.Append(' ');
                }
                else
                {
                    i++;
                }
            }
        }

        bool At(string s) => string.CompareOrdinal(text, i, s, 0, s.Length) == 0;
    }

    [GeneratedRegex(@"^namespace\s+([\w.]+)\s*;", RegexOptions.Multiline)]
    private static partial Regex NamespaceDeclaration();

    [GeneratedRegex(@"OmronHostLink\.Gateway\.(\w+)")]
    private static partial Regex NamespaceName();

    [GeneratedRegex(@"^(?:(?:public|internal|static|sealed|partial|abstract|readonly)\s+)*(?:class|record|interface|enum|struct)\s+(\w+)", RegexOptions.Multiline)]
    private static partial Regex TopLevelType();

    [GeneratedRegex("cref=\"([^\"]+)\"")]
    private static partial Regex CrefReference();
}
