namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// A FINS memory address as a row describes it for a diagnostic view (the console's <c>explain</c>): the area code and its name, the address in CX-Programmer form
/// where the area has one (null for forced-status areas, registers, task flags and the EM current bank), word and bit.
/// </summary>
internal sealed record FinsAddressField(string AreaCode, string Area, string? Address, long Word, long Bit)
{
    /// <summary>What 2301 FORCED SET/RESET does to the bit; null for a plain address (left out of JSON).</summary>
    public string? Action { get; init; }

    /// <summary>The field for <paramref name="address"/>.</summary>
    public static FinsAddressField Of(FinsMemoryAddress address, string? action = null)
        => new(address.AreaCode.ToString("X2", System.Globalization.CultureInfo.InvariantCulture), FinsMemoryArea.Describe(address.AreaCode), PlcAddressOf(address), address.Word, address.Bit)
        {
            Action = action,
        };

    /// <summary>Adds the fields of one address (areaCode, area, address, word, bit) to a command's fields.</summary>
    public static void AddTo(ICommandFields fields, FinsMemoryAddress address)
    {
        FinsAddressField field = Of(address);
        fields.Field("areaCode", field.AreaCode);
        fields.Field("area", field.Area);
        fields.Field("address", field.Address);
        fields.Field("word", field.Word);
        fields.Field("bit", field.Bit);
    }

    /// <summary>For people: <c>D100 (DM word, area 82)</c>, or word.bit where the area has no CX-Programmer address.</summary>
    public override string ToString()
        => $"{(Action is null ? string.Empty : Action + " ")}{Address ?? $"{Word}.{Bit:D2}"} ({Area}, area {AreaCode})";

    /// <summary>
    /// The CX-Programmer address of a FINS address (<c>D100</c>, <c>CIO1.05</c>, <c>T5</c>), read back with the
    /// library's own area map; null where there is none or the address lies outside the area.
    /// </summary>
    private static string? PlcAddressOf(FinsMemoryAddress a)
    {
        if (a.AreaCode is FinsMemoryArea.EmCurrentBankWord or FinsMemoryArea.EmCurrentBankBit
            || !FinsAddressing.TryLocate(a.AreaCode, a.Word, 0, out PlcArea area, out int word, out int bank))
        {
            return null;
        }

        try
        {
            bool bit = a.IsBit && area is not (PlcArea.Timer or PlcArea.Counter);
            return (bit ? PlcAddress.BitOf(area, word, a.Bit, bank) : PlcAddress.WordOf(area, word, bank)).ToString();
        }
        catch (ArgumentException)
        {
            return null;
        }
    }
}
