namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// A received FINS command as the PLC side sees it: the Host Link unit, the FINS header (with the response wait
/// time), the command code and the raw parameters. <see cref="ToCommand"/> rebuilds the typed command; a simulator
/// keeps <see cref="Header"/> to answer even a command whose parameters are refused.
/// </summary>
internal sealed class FinsCommandMessage
{
    private readonly byte[] _parameters;

    /// <summary>Creates the message.</summary>
    public FinsCommandMessage(int unit, FinsHeader header, ushort commandCode, ReadOnlySpan<byte> parameters)
    {
        Unit = unit;
        Header = header;
        CommandCode = commandCode;
        _parameters = parameters.ToArray();
    }

    /// <summary>The Host Link unit number the command was addressed to (-1 when not known).</summary>
    public int Unit { get; }

    /// <summary>The FINS header and the response wait time.</summary>
    public FinsHeader Header { get; }

    /// <summary>The command code, MRC × 256 + SRC.</summary>
    public ushort CommandCode { get; }

    /// <summary>The raw parameter bytes.</summary>
    public ReadOnlyMemory<byte> Parameters => _parameters;

    /// <summary>The typed command, as the rows of <paramref name="table"/> (default: the standard table) read it (see <see cref="FinsCommand.Parse"/>).</summary>
    /// <exception cref="FinsFormatException">The parameters do not fit the command; its end code is the answer to send.</exception>
    public FinsCommand ToCommand(FinsCommandTable? table = null) => (table ?? FinsCommandTable.Standard).Parse(CommandCode, _parameters);
}
