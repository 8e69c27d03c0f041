using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Writes;

/// <summary>
/// Which groups can be written: not a timer/counter completion flag (the PLC sets it), a bit group only as one bit, and
/// only within what the command set writes. The start-up check applies it to every group marked <c>Writable</c>, and
/// every write applies it again before the wire.
/// </summary>
internal sealed class WritableRule : IGroupRule
{
    /// <inheritdoc/>
    public void CheckGroup(ConfiguredGroup group, LinkOptions link, List<string> failures)
    {
        PollGroupOptions options = group.Options;

        if (options.Writable
            && PlcAddress.TryParse(options.Address, out PlcAddress address)
            && PlcValueTypes.TryParse(options.Type, out PlcValueType type)
            && options.Count >= 1
            && Problem(address, type, options.Count, link.CommandSet) is { } problem)
        {
            failures.Add($"{group.KeyOf("Writable")}: {problem}");
        }
    }

    /// <summary>Why <paramref name="count"/> × <paramref name="type"/> from <paramref name="address"/> cannot be written; null when it can.</summary>
    public static string? Problem(PlcAddress address, PlcValueType type, int count, HostLinkCommandSet commandSet)
    {
        if (type == PlcValueType.Bit)
        {
            if (address.Area is PlcArea.Timer or PlcArea.Counter)
            {
                return $"{address} is a timer/counter completion flag, which the PLC sets itself; it cannot be written.";
            }

            if (count != 1)
            {
                return $"a writable bit group must have Count 1 (one bit, written on its own); it has {count}.";
            }
        }

        try
        {
            int words = type switch
            {
                PlcValueType.Bit => 1,
                PlcValueType.String => PlcWords.WordsForString(count),
                _ => type.WordsPerValue() * count,
            };
            // A bit is written with FINS MEMORY AREA WRITE whatever the link's protocol.
            address.AsWord().EnsureRange(words, type == PlcValueType.Bit ? HostLinkCommandSet.Fins : commandSet, forWrite: true);
            return null;
        }
        catch (ArgumentException e)
        {
            return $"{address} cannot be written: {ErrorText.Of(e)}";
        }
    }
}
