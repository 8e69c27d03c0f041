namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// A FINS command: its row (<see cref="FinsCommandRow"/>: code, name, effect, longest answer) and its parameters. Each
/// command this library models is a small immutable subtype that validates its values when constructed;
/// <see cref="Parse"/> rebuilds the typed command from received bytes (codes it does not model become a
/// <see cref="RawFinsCommand"/>).
/// </summary>
/// <remarks>Two commands are equal when they have the same type, code and parameter bytes.</remarks>
internal abstract class FinsCommand : IEquatable<FinsCommand>
{
    /// <summary>
    /// The most parameter bytes a command may carry: what fits in a 1,115-character FA frame with a network header
    /// (1,115 − 34 characters of framing and header, halved) [unverified for commands: the manuals state the limit
    /// for responses].
    /// </summary>
    public const int MaxParameterLength = 540;

    /// <summary>Creates a command.</summary>
    protected FinsCommand()
    {
    }

    /// <summary>The command's row in the command table: code, name, effect and longest answer.</summary>
    public abstract FinsCommandRow Row { get; }

    /// <summary>The command code, MRC × 256 + SRC (for example 0x0101).</summary>
    public ushort CommandCode => Row.Code;

    /// <summary>What repeating this command would do. Default: the row's.</summary>
    public virtual CommandEffect Effect => Row.Effect;

    /// <summary>The most data bytes after MRES SRES the answer to this command can carry. Default: the row's.</summary>
    public virtual int MaxResponseDataLength => Row.MaxResponseData;

    /// <summary>How many parameter bytes follow MRC SRC.</summary>
    public abstract int ParameterLength { get; }

    /// <summary>Writes the <see cref="ParameterLength"/> raw parameter bytes.</summary>
    /// <exception cref="ArgumentException"><paramref name="destination"/> is too small.</exception>
    public abstract void WriteParameters(Span<byte> destination);

    /// <summary>The parameter bytes as a new array.</summary>
    public byte[] GetParameters()
    {
        var bytes = new byte[ParameterLength];
        WriteParameters(bytes);
        return bytes;
    }

    /// <summary>
    /// Rebuilds the typed command from a command code and its raw parameter bytes (the PLC's view of a command).
    /// </summary>
    /// <returns>The typed command, or a <see cref="RawFinsCommand"/> for a code this library does not model.</returns>
    /// <exception cref="FinsFormatException">
    /// The parameters do not fit the command; <see cref="FinsFormatException.EndCode"/> is the response code to answer
    /// (1001 too long, 1002 too short, 1003 element count and data disagree, 1101 unknown area, 1103 address out of
    /// range, 110B response too long, 110C parameter error).
    /// </exception>
    public static FinsCommand Parse(ushort commandCode, ReadOnlySpan<byte> parameters) => FinsCommandTable.Standard.Parse(commandCode, parameters);

    /// <inheritdoc/>
    public bool Equals(FinsCommand? other)
        => other is not null && other.GetType() == GetType() && other.CommandCode == CommandCode
            && other.GetParameters().AsSpan().SequenceEqual(GetParameters());

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is FinsCommand other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode()
    {
        int hash = CommandCode;
        foreach (byte b in GetParameters())
        {
            hash = (hash * 31) + b;
        }

        return hash;
    }

    /// <summary>The command code, its name and its parameters in hex.</summary>
    public override string ToString()
    {
        byte[] parameters = GetParameters();
        var text = new byte[parameters.Length * 2];
        FinsBytes.WriteHex(parameters, text);
        return $"{Row.CodeText} {Row.Name}" + (text.Length == 0 ? string.Empty : " " + FrameText.Printable(text));
    }

    /// <summary>Throws unless <paramref name="destination"/> holds <see cref="ParameterLength"/> bytes.</summary>
    /// <exception cref="ArgumentException">The destination is too small.</exception>
    protected void CheckDestination(Span<byte> destination)
    {
        if (destination.Length < ParameterLength)
        {
            throw new ArgumentException($"FINS {CommandCode:X4} needs {ParameterLength} bytes for its parameters; the destination holds {destination.Length}.", nameof(destination));
        }
    }

    /// <summary>Throws the <see cref="FinsFormatException"/> for parameters whose length is outside <paramref name="min"/>–<paramref name="max"/>.</summary>
    internal static void CheckLength(ushort code, ReadOnlySpan<byte> parameters, int min, int max)
    {
        if (parameters.Length < min)
        {
            throw new FinsFormatException(FinsEndCodes.CommandTooShort, $"FINS {code:X4} needs at least {min} parameter bytes; it carries {parameters.Length}.");
        }

        if (parameters.Length > max)
        {
            throw new FinsFormatException(FinsEndCodes.CommandTooLong, $"FINS {code:X4} takes at most {max} parameter bytes; it carries {parameters.Length}.");
        }
    }
}
