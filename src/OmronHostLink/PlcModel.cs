namespace OmronHostLink;

/// <summary>What MM (PLC MODEL READ) reports: a model code and the family it names.</summary>
public sealed class PlcModel
{
    /// <summary>Creates the model.</summary>
    public PlcModel(byte code)
    {
        Code = code;
        Name = NameOf(code);
    }

    /// <summary>The model code as received (two hex digits).</summary>
    public byte Code { get; }

    /// <summary>The model family, or "unknown model code XX".</summary>
    public string Name { get; }

    /// <summary>
    /// The family for a model code. The table follows the C200H-series and CQM1H Host Link manuals' MM page;
    /// CS/CJ answer 30.
    /// </summary>
    public static string NameOf(byte code) => code switch
    {
        0x01 => "C250",
        0x02 => "C500",
        0x03 => "C120/C50",
        0x09 => "C250F",
        0x0A => "C500F",
        0x0B => "C120F",
        0x0E => "C2000",
        0x10 => "C1000H",
        0x11 => "C2000H/CQM1/CPM1",
        0x12 => "C20H/C28H/C40H/C200H/C200HS/C200HX/HG/HE",
        0x20 => "CV500",
        0x21 => "CV1000",
        0x22 => "CV2000",
        0x30 => "CS/CJ",
        0x40 => "CVM1-CPU01",
        0x41 => "CVM1-CPU11",
        0x42 => "CVM1-CPU21",
        _ => $"unknown model code {code:X2}",
    };

    /// <inheritdoc/>
    public override string ToString() => $"{Name} (code {Code:X2})";
}
