namespace OmronHostLink;

/// <summary>
/// The one answer for bit writes on a C-mode view: C-mode has no bit write, so a C-mode view refuses one (before
/// anything is sent) and says how to make it: FINS, or a read-modify-write the caller opted into. Bit reads go with the
/// view's command set too, so every bit a view can write it can read back.
/// </summary>
public partial class HostLinkUnit
{
    /// <summary>
    /// The refusal of a write of <paramref name="count"/> bits from <paramref name="address"/> by a C-mode view (without
    /// <see cref="HostLinkClientOptions.AllowReadModifyWriteBits"/>), naming the ways to make it.
    /// </summary>
    internal ArgumentException BitWriteRefusal(PlcAddress address, int count)
    {
        PlcAddress first = address.AsWord();
        int words = UnitCommandSet.WordsCovered(address, count);
        string what = count == 1 ? address.ToString() : $"{count} bits from {address}";
        string covered = words == 1 ? first.ToString() : $"{first}-{first.Offset(words - 1)}";
        string message = $"C-mode has no bit write, so a C-mode client does not write {what} (nothing was sent). To write it, {CommandSetAdvice.UseFins(UnitNumber)}";
        if (CModeReaches(first, words))
        {
            message += "; " + CommandSetAdvice.ReadModifyWrite(covered);
        }

        return new ArgumentException(message + ".", nameof(address));
    }

    private static bool CModeReaches(PlcAddress first, int words)
    {
        try
        {
            first.EnsureRange(words, HostLinkCommandSet.CMode, forWrite: true);
            return true;
        }
        catch (ArgumentException)
        {
            return false;
        }
    }
}
