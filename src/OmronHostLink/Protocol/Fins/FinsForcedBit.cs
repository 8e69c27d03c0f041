namespace OmronHostLink.Protocol.Fins;

/// <summary>One item of 2301 FORCED SET/RESET: the action and the bit it applies to.</summary>
internal readonly struct FinsForcedBit : IEquatable<FinsForcedBit>
{
    /// <summary>Bytes one item takes: action(2) area(1) address(2) bit(1).</summary>
    public const int Length = 6;

    /// <summary>Creates the item.</summary>
    /// <param name="action">What is done to the bit.</param>
    /// <param name="address">The bit (a bit-addressed area).</param>
    /// <exception cref="ArgumentException">The address is not in a bit-addressed area.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The action is not one of <see cref="FinsForceAction"/>.</exception>
    public FinsForcedBit(FinsForceAction action, FinsMemoryAddress address)
    {
        if (!IsDefined(action))
        {
            throw new ArgumentOutOfRangeException(nameof(action), action, "Not a FORCED SET/RESET action.");
        }

        if (!address.IsBit)
        {
            throw new ArgumentException($"FORCED SET/RESET applies to bits; area {address.AreaCode:X2} ({FinsMemoryArea.Describe(address.AreaCode)}) is not bit-addressed.", nameof(address));
        }

        Action = action;
        Address = address;
    }

    /// <summary>What is done to the bit.</summary>
    public FinsForceAction Action { get; }

    /// <summary>The bit.</summary>
    public FinsMemoryAddress Address { get; }

    /// <summary>Writes the 6 bytes of the item.</summary>
    public void Write(Span<byte> destination)
    {
        FinsBytes.WriteUInt16(destination, 0, (ushort)Action);
        Address.Write(destination.Slice(2));
    }

    /// <summary>Reads an item from 6 bytes of a command.</summary>
    /// <exception cref="FinsFormatException">110C for an unknown action, 1101 for an area that is not bit-addressed or unknown, 1103 for a bit out of range.</exception>
    public static FinsForcedBit Read(ReadOnlySpan<byte> source)
    {
        var action = (FinsForceAction)FinsBytes.ReadUInt16(source, 0);
        if (!IsDefined(action))
        {
            throw new FinsFormatException(FinsEndCodes.ParameterError, $"FORCED SET/RESET designation {(ushort)action:X4} is not 0000, 0001, 8000, 8001 or FFFF.");
        }

        FinsMemoryAddress address = FinsMemoryAddress.Read(source.Slice(2));
        if (!address.IsBit)
        {
            throw new FinsFormatException(FinsEndCodes.AreaClassificationMissing, $"FORCED SET/RESET applies to bits; area {address.AreaCode:X2} is not bit-addressed.");
        }

        return new FinsForcedBit(action, address);
    }

    /// <inheritdoc/>
    public bool Equals(FinsForcedBit other) => Action == other.Action && Address == other.Address;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is FinsForcedBit other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => ((int)Action * 397) ^ Address.GetHashCode();

    /// <summary>The action and the address.</summary>
    public override string ToString() => $"{Action} {Address}";

    /// <summary>Equality.</summary>
    public static bool operator ==(FinsForcedBit left, FinsForcedBit right) => left.Equals(right);

    /// <summary>Inequality.</summary>
    public static bool operator !=(FinsForcedBit left, FinsForcedBit right) => !left.Equals(right);

    private static bool IsDefined(FinsForceAction action)
        => action is FinsForceAction.ForceReset or FinsForceAction.ForceSet or FinsForceAction.ReleaseToOff
            or FinsForceAction.ReleaseToOn or FinsForceAction.Release;
}
