using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0501 CPU UNIT DATA READ: model, version and configuration of the CPU Unit. Parameter (optional): one byte
/// selecting the data (00 = all) [unverified: the meaning of other values].
/// </summary>
internal sealed class CpuUnitDataReadCommand : FinsCommand
{
    /// <summary>The command code, 0501.</summary>
    public const ushort Code = 0x0501;

    /// <summary>The command's row: 0501 CPU UNIT DATA READ.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "CPU UNIT DATA READ", CommandEffect.ReadOnly, FinsCpuUnitData.MaxLength) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (_, plc) =>
        {
            FinsCpuUnitData unit = plc.UnitData;
            var data = new byte[unit.Length];
            unit.Write(data);
            return FinsReply.Ok(data);
        },
        DescribeCommand = static (command, fields) => fields.Field("selector", ((CpuUnitDataReadCommand)command).Selector is { } selector ? selector.ToString("X2", CultureInfo.InvariantCulture) : null),
        DescribeAnswer = static (data, fields) =>
        {
            FinsCpuUnitData unit = FinsCpuUnitData.Read(data);
            fields.Field("model", unit.Model);
            fields.Field("version", unit.Version);
        },
    };

    /// <summary>Reads the CPU Unit data with no parameter.</summary>
    public CpuUnitDataReadCommand()
    {
    }

    /// <summary>Reads the CPU Unit data with the given selector byte (00 = all data).</summary>
    public CpuUnitDataReadCommand(byte selector) => Selector = selector;

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => Selector is null ? 0 : 1;

    /// <summary>The selector byte sent, if any.</summary>
    public byte? Selector { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        if (Selector is byte selector)
        {
            destination[0] = selector;
        }
    }

    internal static CpuUnitDataReadCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 0, 1);
        return parameters.Length == 0 ? new CpuUnitDataReadCommand() : new CpuUnitDataReadCommand(parameters[0]);
    }
}
