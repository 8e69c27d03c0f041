namespace OmronHostLink;

/// <summary>The rules behind <see cref="PlcAddress.EnsureRange"/>: what a transfer may touch, per command set.</summary>
internal static class AddressRangeCheck
{
    public static void Ensure(PlcAddress start, int count, HostLinkCommandSet commandSet, bool forWrite)
    {
        if (count < 1)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"A transfer at {start} needs at least 1 word; count was {count}.");
        }

        if (commandSet is not (HostLinkCommandSet.CMode or HostLinkCommandSet.Fins))
        {
            throw new ArgumentOutOfRangeException(nameof(commandSet), commandSet, $"{commandSet} is not a Host Link command set.");
        }

        var area = start.Area;
        var end = (long)start.Word + count; // exclusive
        if (end > PlcAreaInfo.Size(area))
        {
            throw new ArgumentOutOfRangeException(
                nameof(count),
                count,
                $"{count} words from {start} run past the end of the {PlcAreaInfo.Extent(area, start.Bank)}.");
        }

        // The CPU owns A0–A447; both WJ and FINS 0102 refuse them, so refuse before the wire.
        if (forWrite && area == PlcArea.Auxiliary && start.Word < PlcAreaInfo.FirstWritableAuxiliaryWord)
        {
            throw new ArgumentException(
                $"{start} is in the read-only part of the auxiliary area (A0–A447); writes can go to A448–A959 only.");
        }

        if (commandSet == HostLinkCommandSet.CMode)
        {
            EnsureCMode(start, (int)end, forWrite);
        }
    }

    // C-mode on CS/CJ cannot reach W at all, nor D/EM 10000+, nor T/C 2048+ (W342 p128).
    private static void EnsureCMode(PlcAddress start, int end, bool forWrite)
    {
        var area = start.Area;
        if (area == PlcArea.Work)
        {
            throw new ArgumentException($"{start}: the work area (W) is not reachable with C-mode commands; {CommandSetAdvice.UseFins()}.");
        }

        var limit = PlcAreaInfo.CModeLimit(area);
        if (end <= limit)
        {
            return;
        }

        var what = area is PlcArea.Timer or PlcArea.Counter
            ? $"{(area == PlcArea.Timer ? "timer" : "counter")} numbers (0–{limit - 1})"
            : $"{PlcAreaInfo.Name(area)} (0–{limit - 1})";
        var command = PlcAreaInfo.CModeCommand(area, forWrite);
        var count = end - start.Word;
        var message = start.Word >= limit
            ? $"{start.AsWord()} is beyond the {what} reachable with C-mode {command}; {CommandSetAdvice.UseFins()}."
            : $"{count} words from {start.AsWord()} reach {PlcAreaInfo.Format(area, end - 1, -1, start.Bank)}, beyond the {what} reachable with C-mode {command}; transfer fewer words, or {CommandSetAdvice.UseFins()}.";
        throw new ArgumentOutOfRangeException(nameof(count), count, message);
    }
}
