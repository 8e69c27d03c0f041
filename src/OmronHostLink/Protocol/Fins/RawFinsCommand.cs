namespace OmronHostLink.Protocol.Fins;

/// <summary>A FINS command this library does not model: its code and parameter bytes as they are.</summary>
internal sealed class RawFinsCommand : FinsCommand
{
    private readonly byte[] _parameters;

    /// <summary>Creates the command.</summary>
    /// <param name="commandCode">MRC × 256 + SRC.</param>
    /// <param name="parameters">The parameter bytes (copied), at most <see cref="FinsCommand.MaxParameterLength"/>.</param>
    /// <exception cref="ArgumentOutOfRangeException">Too many parameter bytes.</exception>
    public RawFinsCommand(ushort commandCode, ReadOnlySpan<byte> parameters)
    {
        if (parameters.Length > MaxParameterLength)
        {
            throw new ArgumentOutOfRangeException(nameof(parameters), parameters.Length, $"A FINS command carries at most {MaxParameterLength} parameter bytes.");
        }

        Row = new FinsCommandRow(commandCode, FinsCommandTable.Standard.Describe(commandCode), CommandEffect.NotRepeatable, FinsMessage.MaxResponseDataLength);
        _parameters = parameters.ToArray();
    }

    /// <summary>A row of its own: the code, its name if the library knows one, never repeated, any answer that fits a frame.</summary>
    public override FinsCommandRow Row { get; }

    /// <inheritdoc/>
    public override int ParameterLength => _parameters.Length;

    /// <summary>The parameter bytes.</summary>
    public ReadOnlyMemory<byte> Parameters => _parameters;

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        _parameters.CopyTo(destination);
    }
}
