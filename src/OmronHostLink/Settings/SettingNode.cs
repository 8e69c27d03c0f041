namespace OmronHostLink;

/// <summary>
/// Flat <c>key:path = value</c> pairs, as configuration gives them, as a tree: a key with children is a section.
/// Keys match without regard to case; the first spelling seen is kept for messages.
/// </summary>
internal sealed class SettingNode
{
    private readonly List<SettingNode> _children = new();

    private SettingNode(string key) => Key = key;

    public string Key { get; }

    /// <summary>The value written at this key; null for a section or a null in the file.</summary>
    public string? Value { get; private set; }

    public IReadOnlyList<SettingNode> Children => _children;

    public static SettingNode From(IEnumerable<KeyValuePair<string, string?>> values)
    {
        var root = new SettingNode("");
        foreach (KeyValuePair<string, string?> pair in values)
        {
            if (pair.Key.Length == 0)
            {
                continue;
            }

            SettingNode node = root;
            foreach (string part in pair.Key.Split(':'))
            {
                SettingNode? child = node._children.Find(c => c.Key.Equals(part, StringComparison.OrdinalIgnoreCase));
                if (child is null)
                {
                    child = new SettingNode(part);
                    node._children.Add(child);
                }

                node = child;
            }

            node.Value = pair.Value ?? node.Value;
        }

        return root;
    }
}
