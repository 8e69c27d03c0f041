namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The FINS commands this library models, as rows (<see cref="FinsCommandRow"/>): what the parser, the simulator,
/// <c>explain</c> and the client look a command code up in. <see cref="Standard"/> is the library's set; <see cref="With"/> extends a table.
/// </summary>
internal sealed class FinsCommandTable
{
    private readonly FinsCommandRow[] _rows;

    private FinsCommandTable(FinsCommandRow[] rows) => _rows = rows;

    /// <summary>The commands of W342 section 5 this library sends and the simulator answers.</summary>
    public static FinsCommandTable Standard { get; } = new(
    [
        MemoryAreaReadCommand.CommandRow,
        MemoryAreaWriteCommand.CommandRow,
        MemoryAreaFillCommand.CommandRow,
        MultipleMemoryAreaReadCommand.CommandRow,
        MemoryAreaTransferCommand.CommandRow,
        RunCommand.CommandRow,
        StopCommand.CommandRow,
        CpuUnitDataReadCommand.CommandRow,
        FinsCommands.CpuUnitStatusRead,
        CycleTimeReadCommand.CommandRow,
        FinsCommands.ClockRead,
        ClockWriteCommand.CommandRow,
        ErrorClearCommand.CommandRow,
        ErrorLogReadCommand.CommandRow,
        ForcedSetResetCommand.CommandRow,
        FinsCommands.ForcedCancel,
    ]);

    /// <summary>The rows, by command code.</summary>
    public IReadOnlyList<FinsCommandRow> Rows => _rows;

    /// <summary>This table with <paramref name="rows"/> added; a row whose code is already present replaces it.</summary>
    public FinsCommandTable With(params FinsCommandRow[] rows)
        => new FinsCommandTable(TableRows.With(_rows, rows, r => r.Code));

    /// <summary>The row of a command code, or null.</summary>
    public FinsCommandRow? Find(ushort code)
    {
        foreach (FinsCommandRow row in _rows)
        {
            if (row.Code == code)
            {
                return row;
            }
        }

        return null;
    }

    /// <summary>The manuals' name of a command code, or null for a code the table does not hold.</summary>
    public string? Name(ushort code) => Find(code)?.Name;

    /// <summary>The manuals' name of a command code, or its hex digits for a code the table does not hold.</summary>
    public string Describe(ushort code) => Name(code) ?? $"command {code:X4}";

    /// <summary>
    /// Rebuilds the typed command from a command code and its raw parameter bytes (the PLC's view of a command): the
    /// row's parser, or a <see cref="RawFinsCommand"/> for a code without one.
    /// </summary>
    /// <exception cref="FinsFormatException">The parameters do not fit the command (see <see cref="FinsCommand.Parse"/>).</exception>
    public FinsCommand Parse(ushort code, ReadOnlySpan<byte> parameters)
    {
        if (parameters.Length > FinsCommand.MaxParameterLength)
        {
            throw new FinsFormatException(FinsEndCodes.CommandTooLong, $"FINS {code:X4} carries {parameters.Length} parameter bytes; at most {FinsCommand.MaxParameterLength} fit in a Host Link frame.");
        }

        return Find(code)?.Parse is { } parse ? parse(parameters) : new RawFinsCommand(code, parameters);
    }
}
