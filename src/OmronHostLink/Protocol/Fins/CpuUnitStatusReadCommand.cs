namespace OmronHostLink.Protocol.Fins;

/// <summary>0601 CPU UNIT STATUS READ: operating status, mode and errors (see <see cref="FinsCpuStatus"/>). No parameters.</summary>
internal sealed class CpuUnitStatusReadCommand : FinsCommand
{
    /// <summary>The command code, 0601.</summary>
    public const ushort Code = 0x0601;

    /// <summary>The command's row: 0601 CPU UNIT STATUS READ.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "CPU UNIT STATUS READ", CommandEffect.ReadOnly, FinsCpuStatus.Length) { Parse = static p => ParseParameters(p) };

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 0;

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
    }

    internal static CpuUnitStatusReadCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 0, 0);
        return new CpuUnitStatusReadCommand();
    }
}
