using System.Text;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>
/// What one Omron PLC model (or family) has and accepts over Host Link: its memory areas and ranges (with the read-only
/// ones), its C-mode commands, whether it takes FINS, how it codes timer/counter present values, the largest frame,
/// and the code it answers to <c>MM</c> (PLC MODEL READ). Every range names the manual page it comes from.
/// </summary>
/// <remarks>The profiles are listed in <c>docs/models.md</c>; <see cref="All"/> holds them.</remarks>
public sealed class PlcModelProfile
{
    private readonly HashSet<string> _cModeHeaders;
    private readonly HashSet<CModeCommandRow> _cModeCommands;

    internal PlcModelProfile(
        string name,
        string displayName,
        IReadOnlyList<string> aliases,
        byte? modelCode,
        IReadOnlyList<PlcAreaRange> areas,
        IReadOnlyList<PlcAreaRange> zeroReadRanges,
        IReadOnlyList<CModeCommandRow> cModeCommands,
        bool supportsFins,
        bool sharesTimerCounterNumbers,
        TimerCounterCoding timerCounterCoding,
        string source)
    {
        Name = name;
        DisplayName = displayName;
        Aliases = aliases;
        ModelCode = modelCode;
        Areas = areas;
        ZeroReadRanges = zeroReadRanges;
        CModeCommands = cModeCommands;
        _cModeCommands = new HashSet<CModeCommandRow>(cModeCommands);
        CModeHeaders = cModeCommands.Select(c => c.Header).Distinct(StringComparer.Ordinal).ToArray();
        _cModeHeaders = new HashSet<string>(CModeHeaders, StringComparer.Ordinal);
        SupportsFins = supportsFins;
        SharesTimerCounterNumbers = sharesTimerCounterNumbers;
        TimerCounterCoding = timerCounterCoding;
        Source = source;
    }

    /// <summary>The name to configure the model with, e.g. <c>CPM1A</c> or <c>CP1E-E</c>.</summary>
    public string Name { get; }

    /// <summary>The models the profile covers, as messages name them: <c>CPM1/CPM1A</c>, <c>CP1E E-type</c>.</summary>
    public string DisplayName { get; }

    /// <summary>Other names <see cref="Parse"/> accepts for the profile.</summary>
    public IReadOnlyList<string> Aliases { get; }

    /// <summary>The code the model answers to <c>MM</c>; null where no manual found says which.</summary>
    public byte? ModelCode { get; }

    /// <summary>The memory the model has, one range per contiguous run with the same write access.</summary>
    public IReadOnlyList<PlcAreaRange> Areas { get; }

    /// <summary>
    /// Addresses the model does not have but answers a C-mode read of with 0000 and end code 00, as its manual says —
    /// the reason the client refuses reads outside <see cref="Areas"/> before they reach the wire.
    /// </summary>
    public IReadOnlyList<PlcAreaRange> ZeroReadRanges { get; }

    /// <summary>The C-mode header codes the model accepts (RR, RD, WD, MS, MM, QQ, …).</summary>
    public IReadOnlyList<string> CModeHeaders { get; }

    /// <summary>The rows of the C-mode commands the model accepts (the headers of <see cref="CModeHeaders"/>).</summary>
    internal IReadOnlyList<CModeCommandRow> CModeCommands { get; }

    /// <summary>Whether the model takes FINS commands over Host Link (<c>FA</c> frames).</summary>
    public bool SupportsFins { get; }

    /// <summary>Whether the model has the compound read <c>QQ</c> (QQMR/QQIR).</summary>
    public bool SupportsCompoundRead => _cModeCommands.Contains(CompoundCommands.ReadRow);

    /// <summary>
    /// Whether timers and counters share one number space (the TC area of C-series PLCs: TIM 5 and CNT 5 cannot both
    /// exist, and C-mode RC reads TC <c>n</c> as entry <c>n</c>); false on CS/CJ/CP, where counter <c>n</c> is RC entry 2048 + <c>n</c>.
    /// </summary>
    public bool SharesTimerCounterNumbers { get; }

    /// <summary>How the model codes timer/counter present values.</summary>
    public TimerCounterCoding TimerCounterCoding { get; }

    /// <summary>The longest frame the model takes, in characters from <c>@</c> to the terminator (W342 p126; C200HX/CQM1H manuals: 132).</summary>
    public int MaxFrameCharacters => 131;

    /// <summary>Words a C-mode read answer carries in its first frame; later frames carry <see cref="ReadWordsLaterFrames"/>.</summary>
    public int ReadWordsFirstFrame => 30;

    /// <summary>Words a C-mode read answer carries in each frame after the first.</summary>
    public int ReadWordsLaterFrames => 31;

    /// <summary>The manuals the profile comes from.</summary>
    public string Source { get; }

    /// <summary>Every profile, in the order of <c>docs/models.md</c>.</summary>
    public static IReadOnlyList<PlcModelProfile> All => PlcModelTable.Profiles;

    /// <summary>
    /// What is wrong with a model setting (a profile name or alias, or <c>auto</c> to ask the PLC with MM), in the
    /// writer's words, or null when it names one; the rule of every model setting.
    /// </summary>
    internal static string? CheckSetting(string model)
        => SettingRules.IsAutoModel(model) || TryParse(model, out _)
            ? null
            : $"'{model}' is not a known PLC model; use one of {KnownNames()}, or {SettingRules.AutoModel} to ask the PLC (MM)";

    /// <summary>Whether the model accepts the C-mode command with header <paramref name="header"/> (e.g. <c>QQ</c>).</summary>
    /// <param name="header">The two-character header code.</param>
    /// <returns>True when the model accepts it.</returns>
    public bool AcceptsCMode(string header) => header is not null && _cModeHeaders.Contains(header);

    /// <summary>Whether the model has <paramref name="area"/> at all.</summary>
    /// <param name="area">The area.</param>
    /// <returns>True when at least one range of the area exists.</returns>
    public bool Has(PlcArea area)
    {
        foreach (var range in Areas)
        {
            if (range.Area == area)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Whether the model has the word (or bit's word) <paramref name="address"/> names.</summary>
    /// <param name="address">The address.</param>
    /// <returns>True when a range holds it.</returns>
    public bool Contains(PlcAddress address) => Find(address.Area, address.Word, address.Bank) is not null;

    /// <summary>
    /// Checks that <paramref name="count"/> words from <paramref name="start"/> exist on this model (and, for a write,
    /// may be written), with a message in the user's words, e.g. "D2048 is beyond the DM area of a CP1E E-type (D0–D2047)".
    /// </summary>
    /// <param name="start">The first word (for a bit address, its word).</param>
    /// <param name="count">The number of words or timer/counter numbers, at least 1.</param>
    /// <param name="forWrite">Whether the transfer writes.</param>
    /// <exception cref="ArgumentOutOfRangeException">A word is beyond the model's area, or the count is less than 1.</exception>
    /// <exception cref="ArgumentException">The model has no such area, or a word is read-only on it.</exception>
    public void EnsureRange(PlcAddress start, int count, bool forWrite)
    {
        if (count < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"A transfer at {start} needs at least 1 word; count was {count}.");
        }

        var area = start.Area;
        if (!Has(area))
        {
            throw new ArgumentException($"{start}: {WithArticle()} has no {PlcAreaInfo.Name(area)}; it has {AreaList()}.", nameof(start));
        }

        var end = (long)start.Word + count; // exclusive
        var word = start.Word;
        while (word < end)
        {
            var range = Find(area, word, start.Bank);
            if (range is null)
            {
                var missing = PlcAreaInfo.Format(area, word, -1, start.Bank);
                var message = word == start.Word
                    ? $"{start.AsWord()} is beyond the {PlcAreaInfo.Name(area)} of {WithArticle()} ({Extent(area)})."
                    : $"{count} words from {start.AsWord()} reach {missing}, beyond the {PlcAreaInfo.Name(area)} of {WithArticle()} ({Extent(area)}).";
                throw new ArgumentOutOfRangeException(word == start.Word ? nameof(start) : nameof(count), count, message);
            }

            if (forWrite && !range.Writable)
            {
                throw new ArgumentException(
                    $"{PlcAreaInfo.Format(area, word, -1, start.Bank)} is read-only on {WithArticle()} ({range} cannot be written by a host).",
                    nameof(start));
            }

            word = range.Last + 1;
        }
    }

    /// <summary>Whether every word of <paramref name="count"/> from <paramref name="start"/> exists on this model (a read may span them).</summary>
    internal bool Covers(PlcAddress start, int count)
    {
        long end = (long)start.Word + count;
        int word = start.Word;
        while (word < end)
        {
            if (Find(start.Area, word, start.Bank) is not { } range)
            {
                return false;
            }

            word = range.Last + 1;
        }

        return true;
    }

    /// <summary>Checks that the model takes FINS over Host Link.</summary>
    /// <exception cref="NotSupportedException">It does not.</exception>
    public void EnsureFins()
    {
        if (!SupportsFins)
        {
            throw new NotSupportedException($"{Capitalised(WithArticle())} does not take FINS commands over Host Link; {CommandSetAdvice.UseCMode}.");
        }
    }

    /// <summary>Checks that the model accepts the C-mode command <paramref name="header"/>.</summary>
    /// <param name="header">The header code, e.g. <c>QQ</c>.</param>
    /// <param name="what">What the command does, for the message (e.g. "compound read").</param>
    /// <exception cref="NotSupportedException">It does not.</exception>
    public void EnsureCMode(string header, string what)
    {
        if (!AcceptsCMode(header))
        {
            throw new NotSupportedException($"{Capitalised(WithArticle())} does not accept the C-mode {what} ({header}).");
        }
    }

    /// <summary>The extent of <paramref name="area"/> on this model: <c>D0–D1023, D6144–D6655</c>; empty when it has none.</summary>
    /// <param name="area">The area.</param>
    /// <returns>The ranges, adjacent ones joined.</returns>
    public string Extent(PlcArea area)
    {
        var text = new StringBuilder();
        int first = -1, last = -2, banks = 0;
        foreach (var range in Areas)
        {
            if (range.Area != area)
            {
                continue;
            }

            if (range.First == last + 1)
            {
                last = range.Last;
                continue;
            }

            Append(text, area, first, last, banks);
            first = range.First;
            last = range.Last;
            banks = range.BankCount;
        }

        Append(text, area, first, last, banks);
        return text.ToString();
    }

    /// <summary>Finds a profile by name (case-insensitive; spaces, hyphens and slashes ignored): <c>CPM1A</c>, <c>CP1E-E</c>, <c>C200HS</c>, <c>CJ2</c>.</summary>
    /// <param name="name">The model name.</param>
    /// <returns>The profile.</returns>
    /// <exception cref="ArgumentException">The name is not a known model; the message lists the known ones.</exception>
    public static PlcModelProfile Parse(string name)
    {
        Guard.NotNull(name);
        if (!TryParse(name, out var profile))
        {
            throw new ArgumentException($"'{name}' is not a known PLC model; known models: {KnownNames()}.", nameof(name));
        }

        return profile;
    }

    /// <summary>Finds a profile by name as <see cref="Parse"/> does, without throwing.</summary>
    /// <param name="name">The model name.</param>
    /// <param name="profile">The profile when found.</param>
    /// <returns>Whether the name is known.</returns>
    public static bool TryParse(string? name, [System.Diagnostics.CodeAnalysis.NotNullWhen(true)] out PlcModelProfile? profile)
    {
        profile = null;
        if (name is null)
        {
            return false;
        }

        var key = Normalise(name);
        foreach (var candidate in PlcModelTable.Profiles)
        {
            if (Normalise(candidate.Name) == key)
            {
                profile = candidate;
                return true;
            }

            foreach (var alias in candidate.Aliases)
            {
                if (Normalise(alias) == key)
                {
                    profile = candidate;
                    return true;
                }
            }
        }

        return false;
    }

    /// <summary>
    /// The profile to assume for a PLC that answered <c>MM</c> with <paramref name="modelCode"/>. Where one code covers
    /// several models (11: CQM1, CPM1/CPM1A, CPM2A/CPM2C, SRM1, CQM1H; 12: C200H, C200HS, C200HX/HG/HE), it is the part
    /// every one of them has — so nothing is read that one of them would answer with 0000 — and its
    /// <see cref="DisplayName"/> says so.
    /// </summary>
    /// <param name="modelCode">The code MM answered.</param>
    /// <returns>The profile, or null for a code no profile answers.</returns>
    public static PlcModelProfile? FromModelCode(byte modelCode) => PlcModelTable.ForModelCode(modelCode);

    /// <summary>A multi-line description: areas and ranges with their sources, commands, FINS, timer/counter coding.</summary>
    /// <returns>The text.</returns>
    public string Describe()
    {
        var text = new StringBuilder();
        text.Append(DisplayName).Append(" (").Append(Name).Append(')').AppendLine();
        text.Append("  MM model code: ").AppendLine(ModelCode is { } code ? code.ToString("X2", System.Globalization.CultureInfo.InvariantCulture) : "unknown (not in the manuals found)");
        text.AppendLine("  areas:");
        foreach (var range in Areas)
        {
            text.Append("    ").Append(range.ToString().PadRight(28)).Append(range.Writable ? "read/write  " : "read-only   ")
                .Append(range.Verified ? string.Empty : "[unverified] ").AppendLine(range.Source);
        }

        foreach (var range in ZeroReadRanges)
        {
            text.Append("    ").Append(range.ToString().PadRight(28)).Append("not present: the PLC reads 0000 here; refused  ")
                .Append(range.Verified ? string.Empty : "[unverified] ").AppendLine(range.Source);
        }

        text.Append("  C-mode: ").AppendLine(string.Join(" ", CModeHeaders));
        text.Append("  FINS over Host Link: ").AppendLine(SupportsFins ? "yes" : "no");
        text.Append("  compound read (QQ): ").AppendLine(SupportsCompoundRead ? "yes" : "no");
        text.Append("  timer/counter PVs: ").AppendLine(TimerCounterCoding == TimerCounterCoding.Bcd ? "BCD" : "BCD, or binary where the PLC's properties say so");
        text.Append("  timers and counters: ").AppendLine(SharesTimerCounterNumbers ? "one shared TC number space" : "separate numbers (counter n is C-mode entry 2048 + n)");
        text.Append("  largest frame: ").Append(MaxFrameCharacters).Append(" characters; reads carry ").Append(ReadWordsFirstFrame)
            .Append(" words in the first frame, ").Append(ReadWordsLaterFrames).AppendLine(" in each later one");
        text.Append("  source: ").Append(Source);
        return text.ToString();
    }

    /// <inheritdoc/>
    public override string ToString() => DisplayName;

    /// <summary>"a CPM1/CPM1A", "an SRM1": the model as a message names it.</summary>
    internal string WithArticle() => ("AEFHILMNORSX".IndexOf(char.ToUpperInvariant(DisplayName[0])) >= 0 ? "an " : "a ") + DisplayName;

    internal PlcAreaRange? Find(PlcArea area, int word, int bank)
    {
        foreach (var range in Areas)
        {
            if (range.Area == area && range.Contains(word, bank))
            {
                return range;
            }
        }

        return null;
    }

    /// <summary>Whether the word is memory the model lacks but answers a read of with 0000 (<see cref="ZeroReadRanges"/>).</summary>
    internal bool ReadsZero(PlcArea area, int word, int bank)
    {
        foreach (var range in ZeroReadRanges)
        {
            if (range.Area == area && range.Contains(word, bank))
            {
                return true;
            }
        }

        return false;
    }

    internal static string KnownNames() => string.Join(", ", PlcModelTable.Profiles.Select(p => p.Name));

    private string AreaList()
    {
        var names = new List<string>();
        foreach (var range in Areas)
        {
            var name = PlcAreaInfo.Name(range.Area);
            if (!names.Contains(name))
            {
                names.Add(name);
            }
        }

        return string.Join(", ", names);
    }

    private static void Append(StringBuilder text, PlcArea area, int first, int last, int banks)
    {
        if (first < 0)
        {
            return;
        }

        if (text.Length > 0)
        {
            text.Append(", ");
        }

        text.Append(new PlcAreaRange(area, first, last, true, string.Empty, true, banks));
    }

    private static string Capitalised(string text) => char.ToUpperInvariant(text[0]) + text.Substring(1);

    private static string Normalise(string name)
    {
        var text = new StringBuilder(name.Length);
        foreach (var c in name)
        {
            if (c is not (' ' or '-' or '_' or '/' or '\t'))
            {
                text.Append(char.ToUpperInvariant(c));
            }
        }

        return text.ToString();
    }
}
