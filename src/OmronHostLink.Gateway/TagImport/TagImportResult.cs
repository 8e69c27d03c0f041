namespace OmronHostLink.Gateway.TagImport;

/// <summary>
/// What an import file gives: every tag, or — when any row cannot be translated — no tag at all and every such row
/// with its line, so that a file is never imported half.
/// </summary>
internal sealed class TagImportResult
{
    private TagImportResult(IReadOnlyList<ImportedTag> tags, IReadOnlyList<TagImportProblem> problems)
    {
        Tags = tags;
        Problems = problems;
    }

    /// <summary>The tags; empty when there are problems.</summary>
    public IReadOnlyList<ImportedTag> Tags { get; }

    /// <summary>The rows that cannot be translated, by line.</summary>
    public IReadOnlyList<TagImportProblem> Problems { get; }

    /// <summary>True when the file imports whole.</summary>
    public bool Succeeded => Problems.Count == 0;

    internal static TagImportResult From(List<ImportedTag> tags, List<TagImportProblem> problems)
    {
        // Names are unique within a file: a second row of the same name is a problem of its own.
        var first = new Dictionary<string, int>(StringComparer.OrdinalIgnoreCase);
        foreach (ImportedTag tag in tags)
        {
            if (!first.TryAdd(tag.Name, tag.Line))
            {
                problems.Add(new TagImportProblem(tag.Line, $"tag name '{tag.Name}' is already used on line {first[tag.Name]}."));
            }
        }

        if (tags.Count == 0 && problems.Count == 0)
        {
            problems.Add(new TagImportProblem(1, "the file has no tag rows."));
        }

        return problems.Count == 0
            ? new TagImportResult(tags, [])
            : new TagImportResult([], problems.OrderBy(p => p.Line).ToList());
    }
}
