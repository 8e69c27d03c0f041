namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// A FINS command that is only its row and its parameter bytes (0601, 0701, 2302, and any command added to a table as a
/// row alone): everything about it is its row in a <see cref="FinsCommandTable"/>.
/// </summary>
internal sealed class SimpleFinsCommand : FinsCommand
{
    private readonly byte[] _parameters;

    /// <summary>Creates the command of <paramref name="row"/> with <paramref name="parameters"/>.</summary>
    public SimpleFinsCommand(FinsCommandRow row, ReadOnlySpan<byte> parameters = default)
    {
        Row = Guard.NotNull(row);
        if (parameters.Length > MaxParameterLength)
        {
            throw new ArgumentOutOfRangeException(nameof(parameters), parameters.Length, $"A FINS command carries at most {MaxParameterLength} parameter bytes.");
        }

        _parameters = parameters.ToArray();
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row { get; }

    /// <summary>The parameter bytes.</summary>
    public ReadOnlySpan<byte> Parameters => _parameters;

    /// <inheritdoc/>
    public override int ParameterLength => _parameters.Length;

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        _parameters.CopyTo(destination);
    }
}
