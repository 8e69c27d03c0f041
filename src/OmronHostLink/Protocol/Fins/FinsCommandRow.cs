using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>Rebuilds a command from its parameter bytes, as a PLC reads them; refuses with <see cref="FinsFormatException"/>.</summary>
internal delegate FinsCommand FinsParse(ReadOnlySpan<byte> parameters);

/// <summary>Executes a parsed command against the PLC side: the response code and data the PLC answers with.</summary>
internal delegate FinsReply FinsExecute(FinsCommand command, IFinsPlc plc);

/// <summary>Puts a parsed command's parameters, as fields, into <paramref name="fields"/>.</summary>
internal delegate void FinsDescribeCommand(FinsCommand command, ICommandFields fields);

/// <summary>
/// Puts the fields of a normal-completion answer's data into <paramref name="fields"/>; throws
/// <see cref="HostLinkFrameException"/> when the data does not have the answer's shape.
/// </summary>
internal delegate void FinsDescribeAnswer(ReadOnlySpan<byte> data, ICommandFields fields);

/// <summary>
/// One FINS command as the manuals define it, in one place: command code (MRC SRC), the manual's name, what repeating
/// it does, the longest data its answer can carry, and how the PLC side reads its parameters and executes the command,
/// and how a diagnostic view describes its parameters and its answer's data. The parser, the simulator, <c>explain</c>
/// and the client all read these rows. The rows are
/// <see cref="FinsCommandTable"/>; each command type names its row, and one command may narrow the row's facts
/// (0620 that initialises is not repeated; 0101 of n words is answered with 2n bytes).
/// </summary>
internal sealed class FinsCommandRow
{
    /// <summary>Creates a row.</summary>
    /// <param name="code">MRC × 256 + SRC.</param>
    /// <param name="name">The manuals' name (W342 section 5).</param>
    /// <param name="effect">What repeating the command would do.</param>
    /// <param name="maxResponseData">The most data bytes after MRES SRES an answer of this command can carry.</param>
    public FinsCommandRow(ushort code, string name, CommandEffect effect, int maxResponseData)
    {
        if ((uint)maxResponseData > FinsMessage.MaxResponseDataLength)
        {
            throw new ArgumentOutOfRangeException(nameof(maxResponseData), maxResponseData, $"An FA answer carries 0-{FinsMessage.MaxResponseDataLength} data bytes.");
        }

        Code = code;
        Name = Guard.NotNull(name);
        Effect = effect;
        MaxResponseData = maxResponseData;
    }

    /// <summary>The command code, MRC × 256 + SRC.</summary>
    public ushort Code { get; }

    /// <summary>The command code as the manuals write it (<c>0101</c>).</summary>
    public string CodeText => Code.ToString("X4", CultureInfo.InvariantCulture);

    /// <summary>The manuals' name.</summary>
    public string Name { get; }

    /// <summary>What repeating the command would do.</summary>
    public CommandEffect Effect { get; }

    /// <summary>The most data bytes after MRES SRES any command of this row can be answered with.</summary>
    public int MaxResponseData { get; }

    /// <summary>How the PLC reads the parameters; null for a row this library names but does not read.</summary>
    public FinsParse? Parse { get; init; }

    /// <summary>How the PLC executes it; null for a command the PLC answers 0401 (undefined command).</summary>
    public FinsExecute? Execute { get; init; }

    /// <summary>The command's parameters as fields for <c>explain</c>; null for a command without parameters.</summary>
    public FinsDescribeCommand? DescribeCommand { get; init; }

    /// <summary>The fields of a normal-completion answer's data; null when the data does not describe itself.</summary>
    public FinsDescribeAnswer? DescribeAnswer { get; init; }

    /// <inheritdoc/>
    public override string ToString() => $"{CodeText} {Name}";
}
