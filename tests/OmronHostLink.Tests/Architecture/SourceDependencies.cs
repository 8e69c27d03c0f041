using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace OmronHostLink.Tests.Architecture;

/// <summary>
/// Which folder of a project's source uses which, read with the compiler: every name in a file (a type, a member, a
/// constant, an extension method, a <c>nameof</c> or <c>cref</c>) is resolved, and the folder that declares it is a
/// dependency of the file's folder. Folders share namespaces in the core, so the folder, not the namespace, is the unit.
/// Documentation comments are not read: a <c>see cref</c> may point anywhere.
/// </summary>
internal sealed class SourceDependencies
{
    private SourceDependencies(IReadOnlyList<Use> uses) => Uses = uses;

    /// <summary>One use of a name declared in another folder.</summary>
    public sealed record Use(string FromFolder, string FromFile, string ToFolder, string Name);

    /// <summary>Every use of a name declared in another folder of the project.</summary>
    public IReadOnlyList<Use> Uses { get; }

    /// <summary>The folder of a file below the project root: <c>Link</c>, <c>Protocol/Fins</c> → <c>Protocol</c>; <c>.</c> for the root.</summary>
    public static string FolderOf(string projectRoot, string file)
    {
        string relative = Path.GetRelativePath(projectRoot, file).Replace('\\', '/');
        int slash = relative.IndexOf('/', StringComparison.Ordinal);
        return slash < 0 ? "." : relative[..slash];
    }

    /// <summary>The repository's <c>src/</c> folder.</summary>
    public static string SourceRoot() => RepositoryRoot.Combine("src");

    /// <summary>Reads and resolves every C# file of <paramref name="projectRoot"/> (bin and obj left out).</summary>
    public static SourceDependencies Of(string projectRoot)
    {
        string[] files = Directory.GetFiles(projectRoot, "*.cs", SearchOption.AllDirectories)
            .Where(f => !f.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}", StringComparison.Ordinal)
                && !f.Contains($"{Path.DirectorySeparatorChar}bin{Path.DirectorySeparatorChar}", StringComparison.Ordinal))
            .ToArray();
        var options = new CSharpParseOptions(LanguageVersion.Preview, DocumentationMode.Parse, preprocessorSymbols: ["NET", "NET10_0", "NET10_0_OR_GREATER", "NET8_0_OR_GREATER", "NET6_0_OR_GREATER", "NETCOREAPP"]);
        SyntaxTree[] trees = files.Select(f => CSharpSyntaxTree.ParseText(File.ReadAllText(f), options, f)).ToArray();

        // The platform and the packages the test itself runs with; the project's own assemblies are left out, since
        // their types are the source being read.
        IEnumerable<string> platform = ((string)AppContext.GetData("TRUSTED_PLATFORM_ASSEMBLIES")!).Split(Path.PathSeparator);
        IEnumerable<string> packages = Directory.GetFiles(AppContext.BaseDirectory, "*.dll").Where(p => !Path.GetFileName(p).StartsWith("OmronHostLink", StringComparison.Ordinal));
        MetadataReference[] references = platform.Concat(packages).Distinct().Select(p => (MetadataReference)MetadataReference.CreateFromFile(p)).ToArray();
        CSharpCompilation compilation = CSharpCompilation.Create(
            "Layers",
            trees,
            references,
            new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary, nullableContextOptions: NullableContextOptions.Enable, allowUnsafe: true));
        compilation = compilation.AddSyntaxTrees(CSharpSyntaxTree.ParseText("global using System; global using System.Collections.Generic; global using System.IO; global using System.Linq; global using System.Threading; global using System.Threading.Tasks;", options));

        var uses = new List<Use>();
        foreach (SyntaxTree tree in trees)
        {
            SemanticModel model = compilation.GetSemanticModel(tree);
            string from = FolderOf(projectRoot, tree.FilePath);
            foreach (SimpleNameSyntax name in tree.GetRoot().DescendantNodes().OfType<SimpleNameSyntax>())
            {
                SymbolInfo info = model.GetSymbolInfo(name);
                ISymbol? symbol = info.Symbol ?? info.CandidateSymbols.FirstOrDefault();
                if (symbol is null or INamespaceSymbol)
                {
                    continue;
                }

                foreach (string to in DeclaringFolders(projectRoot, symbol))
                {
                    if (to != from)
                    {
                        uses.Add(new Use(from, Path.GetRelativePath(projectRoot, tree.FilePath), to, symbol.ToDisplayString()));
                    }
                }
            }
        }

        return new SourceDependencies(uses);
    }

    private static IEnumerable<string> DeclaringFolders(string projectRoot, ISymbol symbol)
    {
        symbol = symbol is IMethodSymbol { ReducedFrom: { } extension } ? extension : symbol;
        symbol = symbol.OriginalDefinition;

        // A member is where it is declared; a type where any part of it is (a partial type may span folders).
        return symbol.DeclaringSyntaxReferences
            .Select(r => r.SyntaxTree.FilePath)
            .Where(p => p.Length > 0 && p.StartsWith(projectRoot, StringComparison.Ordinal))
            .Select(p => FolderOf(projectRoot, p))
            .Distinct();
    }
}
