namespace OmronHostLink.Protocol.Fins;

/// <summary>2302 FORCED SET/RESET CANCEL: releases every forced bit. No parameters.</summary>
internal sealed class ForcedSetResetCancelCommand : FinsCommand
{
    /// <summary>The command code, 2302.</summary>
    public const ushort Code = FinsCommandCodes.ForcedSetResetCancel;

    /// <inheritdoc/>
    public override ushort CommandCode => Code;

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
