namespace OmronHostLink.Protocol.Fins;

/// <summary>2302 FORCED SET/RESET CANCEL: releases every forced bit. No parameters.</summary>
internal sealed class ForcedSetResetCancelCommand : FinsCommand
{
    /// <summary>The command code, 2302.</summary>
    public const ushort Code = 0x2302;

    /// <summary>The command's row: 2302 FORCED SET/RESET CANCEL.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "FORCED SET/RESET CANCEL", CommandEffect.NotRepeatable, 0) { Parse = static p => ParseParameters(p) };

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 0;

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
    }

    internal static ForcedSetResetCancelCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 0, 0);
        return new ForcedSetResetCancelCommand();
    }
}
