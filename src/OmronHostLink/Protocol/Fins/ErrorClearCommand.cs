using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 2101 ERROR CLEAR: clears one error, or all of them. Parameter: error code(2); <see cref="AllErrors"/> (FFFF)
/// clears every error that can be cleared [unverified: the meaning of FFFE].
/// </summary>
internal sealed class ErrorClearCommand : FinsCommand
{
    /// <summary>The command code, 2101.</summary>
    public const ushort Code = 0x2101;

    /// <summary>The command's row: 2101 ERROR CLEAR.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "ERROR CLEAR", CommandEffect.NotRepeatable, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (_, plc) =>
        {
            plc.ClearErrors();
            return FinsReply.Done;
        },
        DescribeCommand = static (command, fields) => fields.Field("errorCode", ((ErrorClearCommand)command).ErrorCode.ToString("X4", CultureInfo.InvariantCulture)),
    };

    /// <summary>The error code that clears all errors.</summary>
    public const ushort AllErrors = 0xFFFF;

    /// <summary>Creates the command.</summary>
    /// <param name="errorCode">The error to clear; <see cref="AllErrors"/> by default.</param>
    public ErrorClearCommand(ushort errorCode = AllErrors) => ErrorCode = errorCode;

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 2;

    /// <summary>The error code cleared.</summary>
    public ushort ErrorCode { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        FinsBytes.WriteUInt16(destination, 0, ErrorCode);
    }

    internal static ErrorClearCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 2, 2);
        return new ErrorClearCommand(FinsBytes.ReadUInt16(parameters, 0));
    }
}
