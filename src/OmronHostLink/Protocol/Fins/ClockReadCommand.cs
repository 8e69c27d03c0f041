namespace OmronHostLink.Protocol.Fins;

/// <summary>0701 CLOCK READ: the PLC's date and time (see <see cref="FinsClock"/>). No parameters.</summary>
internal sealed class ClockReadCommand : FinsCommand
{
    /// <summary>The command code, 0701.</summary>
    public const ushort Code = FinsCommandCodes.ClockRead;

    /// <inheritdoc/>
    public override ushort CommandCode => Code;

    /// <inheritdoc/>
    public override int ParameterLength => 0;

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
    }

    internal static ClockReadCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 0, 0);
        return new ClockReadCommand();
    }
}
