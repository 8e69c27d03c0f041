namespace OmronHostLink.Protocol.Fins;

/// <summary>0701 CLOCK READ: the PLC's date and time (see <see cref="FinsClock"/>). No parameters.</summary>
internal sealed class ClockReadCommand : FinsCommand
{
    /// <summary>The command code, 0701.</summary>
    public const ushort Code = 0x0701;

    /// <summary>The command's row: 0701 CLOCK READ.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "CLOCK READ", CommandEffect.ReadOnly, FinsClock.Length) { Parse = static p => ParseParameters(p) };

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

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
