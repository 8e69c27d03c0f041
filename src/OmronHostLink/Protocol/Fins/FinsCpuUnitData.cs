namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The response data of 0501 CPU UNIT DATA READ: the model (20 ASCII characters) and version (20), then further
/// configuration data kept raw in <see cref="Remainder"/>.
/// </summary>
public sealed class FinsCpuUnitData
{
    /// <summary>Bytes of the model field.</summary>
    internal const int ModelLength = 20;

    /// <summary>Bytes of the version field.</summary>
    internal const int VersionLength = 20;

    /// <summary>
    /// The most bytes a 0501 answer carries: model, version, system use and area data (20 + 20 + 40 + 12), CPU Bus Unit
    /// configuration (64), remote I/O data (2) and CPU Unit information (1), 159 in all (W342 5-3-15), and one byte to spare.
    /// </summary>
    internal const int MaxLength = 160;

    private readonly byte[] _remainder;

    /// <summary>Creates the data.</summary>
    /// <param name="model">The model, at most 20 printable ASCII characters.</param>
    /// <param name="version">The version, at most 20 printable ASCII characters.</param>
    /// <param name="remainder">The bytes after the version (copied).</param>
    /// <exception cref="ArgumentException">A text is too long or not printable ASCII.</exception>
    public FinsCpuUnitData(string model, string version, ReadOnlySpan<byte> remainder = default)
    {
        FinsBytes.WriteAsciiPadded(Guard.NotNull(model), new byte[ModelLength]);
        FinsBytes.WriteAsciiPadded(Guard.NotNull(version), new byte[VersionLength]);
        Model = model.TrimEnd(' ');
        Version = version.TrimEnd(' ');
        _remainder = remainder.ToArray();
    }

    /// <summary>The CPU Unit model (for example <c>CJ1M-CPU13</c>), trailing spaces removed.</summary>
    public string Model { get; }

    /// <summary>The CPU Unit version, trailing spaces removed.</summary>
    public string Version { get; }

    /// <summary>The data after the version (system area, area data, ...), as received.</summary>
    public ReadOnlyMemory<byte> Remainder => _remainder;

    /// <summary>Bytes <see cref="Write"/> produces.</summary>
    internal int Length => ModelLength + VersionLength + _remainder.Length;

    /// <summary>Decodes the response data.</summary>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.WrongLength"/>: fewer than 40 bytes.</exception>
    internal static FinsCpuUnitData Read(ReadOnlySpan<byte> data)
    {
        if (data.Length < ModelLength + VersionLength)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"CPU UNIT DATA READ data holds {data.Length} bytes; the model and version alone take {ModelLength + VersionLength}.");
        }

        return new FinsCpuUnitData(
            FinsBytes.AsciiTrimmed(data.Slice(0, ModelLength)),
            FinsBytes.AsciiTrimmed(data.Slice(ModelLength, VersionLength)),
            data.Slice(ModelLength + VersionLength));
    }

    /// <summary>Encodes the data (texts padded with spaces) into <paramref name="destination"/>.</summary>
    /// <returns><see cref="Length"/>.</returns>
    internal int Write(Span<byte> destination)
    {
        if (destination.Length < Length)
        {
            throw new ArgumentException("The destination is too small for the CPU Unit data.", nameof(destination));
        }

        FinsBytes.WriteAsciiPadded(Model, destination.Slice(0, ModelLength));
        FinsBytes.WriteAsciiPadded(Version, destination.Slice(ModelLength, VersionLength));
        _remainder.CopyTo(destination.Slice(ModelLength + VersionLength));
        return Length;
    }
}
