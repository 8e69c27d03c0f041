using OmronHostLink.Gateway.TagImport;


namespace OmronHostLink.Gateway.Configuration;

/// <summary>Adds the tags of a link's tag files to its poll groups when the configuration is bound.</summary>
internal static class TagFiles
{
    /// <summary>
    /// Reads each of the link's files and adds one poll group a row. A file with any bad row adds nothing; its problems,
    /// each naming the file and line, are kept on the link for the validator to report at start-up.
    /// </summary>
    public static void AddGroups(LinkOptions link)
    {
        for (int i = 0; i < link.TagFiles.Count; i++)
        {
            TagFileOptions file = link.TagFiles[i];
            string key = $"TagFiles:{i}";
            if (string.IsNullOrWhiteSpace(file.Path))
            {
                link.TagFileProblems.Add($"{key}:Path is empty; name a CSV file of tags.");
                continue;
            }

            // The file's own settings apply to every row: a bad one is named once, by its key, and the file adds nothing.
            int before = link.TagFileProblems.Count;
            if (GatewayOptionsValidator.UnitProblem(file.Unit) is { } unitProblem)
            {
                link.TagFileProblems.Add($"{key}:Unit: {unitProblem}");
            }

            if (GatewayOptionsValidator.IntervalProblem(file.Interval) is { } intervalProblem)
            {
                link.TagFileProblems.Add($"{key}:Interval {intervalProblem}");
            }

            if (GatewayOptionsValidator.LogProblem(file.Log) is { } logProblem)
            {
                link.TagFileProblems.Add($"{key}:Log {logProblem}");
            }

            if (link.TagFileProblems.Count > before)
            {
                continue;
            }

            bool kepware = file.Format.Equals("Kepware", StringComparison.OrdinalIgnoreCase);
            if (!kepware && !file.Format.Equals("Plain", StringComparison.OrdinalIgnoreCase))
            {
                link.TagFileProblems.Add($"{key}:Format '{file.Format}' is not Kepware or Plain.");
                continue;
            }

            TagImportResult result;
            string path = Path.GetFullPath(file.Path);
            try
            {
                using var reader = new StreamReader(path);
                result = kepware ? KepwareTagCsv.Import(reader) : PlainTagCsv.Import(reader);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                link.TagFileProblems.Add($"{key}:Path '{path}' cannot be read: {e.Message}");
                continue;
            }

            if (!result.Succeeded)
            {
                link.TagFileProblems.AddRange(result.Problems.Select(p => $"{key}:Path {path}, {p}"));
                continue;
            }

            foreach (ImportedTag tag in result.Tags)
            {
                if (link.Groups.ContainsKey(tag.Name))
                {
                    link.TagFileProblems.Add($"{key}:Path {path}, line {tag.Line}: tag '{tag.Name}' is already a poll group of this link.");
                    continue;
                }

                link.Groups[tag.Name] = new PollGroupOptions
                {
                    Unit = file.Unit,
                    Address = tag.Address,
                    Type = tag.Type.Name(),
                    Count = tag.Count,
                    Interval = tag.Interval ?? file.Interval,
                    Log = file.Log,
                    Writable = tag.Writable,
                    Row = $"{key}:Path {path}, line {tag.Line}",
                };
            }
        }
    }
}
