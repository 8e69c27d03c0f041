using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// A FINS response code (MRES × 256 + SRES). Bit 15 flags a network relay error, bit 7 a fatal CPU error and bit 6 a
/// non-fatal CPU error; <see cref="Code"/> is the value with those flags masked off (<c>&amp; 0x7F3F</c>).
/// </summary>
public readonly struct FinsEndCode : IEquatable<FinsEndCode>
{
    /// <summary>Bit 15 of a response code: an error occurred while relaying through a network.</summary>
    public const ushort NetworkRelayErrorFlag = 0x8000;

    /// <summary>Bit 7 of a response code: the CPU Unit has a fatal error.</summary>
    public const ushort FatalCpuErrorFlag = 0x0080;

    /// <summary>Bit 6 of a response code: the CPU Unit has a non-fatal error.</summary>
    public const ushort NonFatalCpuErrorFlag = 0x0040;

    /// <summary>Creates the response code from its raw 16-bit value.</summary>
    public FinsEndCode(ushort raw) => Raw = raw;

    /// <summary>The response code as received, flags included.</summary>
    public ushort Raw { get; }

    /// <summary>The response code without its flags.</summary>
    public ushort Code => (ushort)(Raw & ~(NetworkRelayErrorFlag | FatalCpuErrorFlag | NonFatalCpuErrorFlag));

    /// <summary>The main response code (MRES without the relay flag).</summary>
    public byte MainCode => (byte)((Code >> 8) & 0x7F);

    /// <summary>The sub response code (SRES without the CPU flags).</summary>
    public byte SubCode => (byte)(Code & 0x3F);

    /// <summary>Bit 15: an error occurred while relaying through a network.</summary>
    public bool NetworkRelayError => (Raw & NetworkRelayErrorFlag) != 0;

    /// <summary>Bit 7: the CPU Unit has a fatal error.</summary>
    public bool FatalCpuError => (Raw & FatalCpuErrorFlag) != 0;

    /// <summary>Bit 6: the CPU Unit has a non-fatal error.</summary>
    public bool NonFatalCpuError => (Raw & NonFatalCpuErrorFlag) != 0;

    /// <summary>True when the command completed (the CPU flags may still be set).</summary>
    public bool IsSuccess => Code == FinsEndCodes.NormalCompletion;

    /// <summary>Whether the code reports a busy or timed-out network (<see cref="FinsEndCodes.IsTransient"/>).</summary>
    public bool IsTransient => FinsEndCodes.IsTransient(Code);

    /// <summary>The meaning of <see cref="Code"/>, in the manuals' words.</summary>
    public string Meaning => FinsEndCodes.Describe(Code);

    /// <inheritdoc/>
    public bool Equals(FinsEndCode other) => Raw == other.Raw;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is FinsEndCode other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => Raw;

    /// <summary>The code as four hex digits, as the manuals write it.</summary>
    public override string ToString() => Raw.ToString("X4", CultureInfo.InvariantCulture);

    /// <summary>Equality.</summary>
    public static bool operator ==(FinsEndCode left, FinsEndCode right) => left.Equals(right);

    /// <summary>Inequality.</summary>
    public static bool operator !=(FinsEndCode left, FinsEndCode right) => !left.Equals(right);
}
