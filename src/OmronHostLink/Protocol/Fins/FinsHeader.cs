namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The FINS header of a command or response carried over Host Link, plus the Host Link response wait time that
/// precedes a command's header.
/// </summary>
/// <remarks>
/// <para>
/// To the CPU Unit the host is directly connected to, only ICF, DA2, SA2 and SID travel (<see cref="Direct"/>):
/// <c>@</c> unit <c>FA</c> wait ICF DA2 SA2 SID MRC SRC parameters. To a CPU Unit on a network, the full header
/// travels (<see cref="Network"/>): ICF(80) RSV GCT DNA DA1 DA2 SNA SA1 SA2 SID.
/// </para>
/// <para>Bit 7 of ICF (gateway used) selects the long form; bit 6 marks a response.</para>
/// </remarks>
internal readonly struct FinsHeader : IEquatable<FinsHeader>
{
    /// <summary>ICF of a command to the directly connected CPU Unit.</summary>
    public const byte DirectCommandIcf = 0x00;

    /// <summary>ICF of a command to a CPU Unit on a network.</summary>
    public const byte NetworkCommandIcf = 0x80;

    /// <summary>ICF of a response from the directly connected CPU Unit.</summary>
    public const byte DirectResponseIcf = 0x40;

    /// <summary>ICF of a response from a CPU Unit on a network.</summary>
    public const byte NetworkResponseIcf = 0xC0;

    /// <summary>The gateway count commands normally carry.</summary>
    public const byte DefaultGatewayCount = 0x02;

    /// <summary>Bytes of a direct header (ICF DA2 SA2 SID).</summary>
    public const int DirectLength = 4;

    /// <summary>The longest response wait time a Host Link FINS frame carries: one hex digit, in units of 10 ms.</summary>
    public const int MaxResponseWait = SettingRules.MaxFinsResponseWait;

    /// <summary>Bytes of a network header (ICF RSV GCT DNA DA1 DA2 SNA SA1 SA2 SID).</summary>
    public const int NetworkLength = 10;

    private FinsHeader(int responseWait, byte icf, byte rsv, byte gct, byte dna, byte da1, byte da2, byte sna, byte sa1, byte sa2, byte sid)
    {
        ResponseWait = responseWait;
        Icf = icf;
        Rsv = rsv;
        Gct = gct;
        Dna = dna;
        Da1 = da1;
        Da2 = da2;
        Sna = sna;
        Sa1 = sa1;
        Sa2 = sa2;
        Sid = sid;
    }

    /// <summary>
    /// The Host Link response wait time of a command, 0–15, in units of 10 ms [unverified: the unit and range come
    /// from one manual]. Always 0 in a response, which carries no such field.
    /// </summary>
    public int ResponseWait { get; }

    /// <summary>The response wait time as a duration (<see cref="ResponseWait"/> × 10 ms).</summary>
    public TimeSpan ResponseWaitTime => TimeSpan.FromMilliseconds(ResponseWait * 10);

    /// <summary>Information control field: bit 7 gateway (network header), bit 6 response, bit 0 no response required.</summary>
    public byte Icf { get; }

    /// <summary>Reserved byte of a network header (00).</summary>
    public byte Rsv { get; }

    /// <summary>Gateway count of a network header (02 in commands).</summary>
    public byte Gct { get; }

    /// <summary>Destination network address (0 = local network).</summary>
    public byte Dna { get; }

    /// <summary>Destination node address (0 = local node).</summary>
    public byte Da1 { get; }

    /// <summary>Destination unit address (00 = CPU Unit).</summary>
    public byte Da2 { get; }

    /// <summary>Source network address.</summary>
    public byte Sna { get; }

    /// <summary>Source node address.</summary>
    public byte Sa1 { get; }

    /// <summary>Source unit address.</summary>
    public byte Sa2 { get; }

    /// <summary>Service ID: any value the host chooses; the PLC echoes it in the response.</summary>
    public byte Sid { get; }

    /// <summary>True for the long (network) form: ICF bit 7 set.</summary>
    public bool IsNetwork => (Icf & 0x80) != 0;

    /// <summary>True when ICF marks a response (bit 6).</summary>
    public bool IsResponse => (Icf & 0x40) != 0;

    /// <summary>Bytes this header takes in a message: <see cref="DirectLength"/> or <see cref="NetworkLength"/>.</summary>
    public int Length => IsNetwork ? NetworkLength : DirectLength;

    /// <summary>A command header for the CPU Unit the host is directly connected to (ICF 00, DA2 00, SA2 00).</summary>
    /// <param name="sid">Service ID, 0–255, echoed by the PLC.</param>
    /// <param name="responseWait">Response wait time, 0–15 (× 10 ms).</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="responseWait"/> is outside 0–15 or <paramref name="sid"/> outside 0–255.</exception>
    public static FinsHeader Direct(int sid = 0, int responseWait = 0)
    {
        CheckWait(responseWait);
        Guard.InRange(sid, 0, 255);
        return new FinsHeader(responseWait, DirectCommandIcf, 0, 0, 0, 0, 0, 0, 0, 0, (byte)sid);
    }

    /// <summary>A command header for a CPU Unit on a network (ICF 80, RSV 00).</summary>
    /// <param name="dna">Destination network, 0–127 (0 = local network).</param>
    /// <param name="da1">Destination node, 0–255.</param>
    /// <param name="da2">Destination unit, 0–255 (0 = CPU Unit).</param>
    /// <param name="sna">Source network, 0–127.</param>
    /// <param name="sa1">Source node, 0–255.</param>
    /// <param name="sa2">Source unit, 0–255.</param>
    /// <param name="sid">Service ID, 0–255, echoed by the PLC.</param>
    /// <param name="gct">Gateway count, 0–7 (normally 2).</param>
    /// <param name="responseWait">Response wait time, 0–15 (× 10 ms).</param>
    /// <exception cref="ArgumentOutOfRangeException">A field is out of its range.</exception>
    public static FinsHeader Network(int dna, int da1, int da2, int sna, int sa1, int sa2, int sid = 0, int gct = DefaultGatewayCount, int responseWait = 0)
    {
        CheckWait(responseWait);
        Guard.InRange(dna, 0, 127);
        Guard.InRange(da1, 0, 255);
        Guard.InRange(da2, 0, 255);
        Guard.InRange(sna, 0, 127);
        Guard.InRange(sa1, 0, 255);
        Guard.InRange(sa2, 0, 255);
        Guard.InRange(sid, 0, 255);
        Guard.InRange(gct, 0, 7);
        return new FinsHeader(responseWait, NetworkCommandIcf, 0, (byte)gct, (byte)dna, (byte)da1, (byte)da2, (byte)sna, (byte)sa1, (byte)sa2, (byte)sid);
    }

    /// <summary>The same header with another service ID.</summary>
    public FinsHeader WithSid(byte sid) => new(ResponseWait, Icf, Rsv, Gct, Dna, Da1, Da2, Sna, Sa1, Sa2, sid);

    /// <summary>The same header with another response wait time (0–15).</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="responseWait"/> is outside 0–15.</exception>
    public FinsHeader WithResponseWait(int responseWait)
    {
        CheckWait(responseWait);
        return new FinsHeader(responseWait, Icf, Rsv, Gct, Dna, Da1, Da2, Sna, Sa1, Sa2, Sid);
    }

    /// <summary>
    /// The header of the response to a command with this header: ICF 40 (direct) or C0 (network), the same RSV, GCT
    /// and SID, and source and destination addresses swapped.
    /// </summary>
    public FinsHeader ToResponseHeader()
        => IsNetwork
            ? new FinsHeader(0, NetworkResponseIcf, Rsv, Gct, Sna, Sa1, Sa2, Dna, Da1, Da2, Sid)
            : new FinsHeader(0, DirectResponseIcf, 0, 0, 0, 0, Sa2, 0, 0, Da2, Sid);

    /// <summary>Writes the header bytes (not the wait time) into <paramref name="destination"/>.</summary>
    /// <returns><see cref="Length"/>.</returns>
    public int Write(Span<byte> destination)
    {
        if (destination.Length < Length)
        {
            throw new ArgumentException("The destination is too small for the FINS header.", nameof(destination));
        }

        destination[0] = Icf;
        if (!IsNetwork)
        {
            destination[1] = Da2;
            destination[2] = Sa2;
            destination[3] = Sid;
            return DirectLength;
        }

        destination[1] = Rsv;
        destination[2] = Gct;
        destination[3] = Dna;
        destination[4] = Da1;
        destination[5] = Da2;
        destination[6] = Sna;
        destination[7] = Sa1;
        destination[8] = Sa2;
        destination[9] = Sid;
        return NetworkLength;
    }

    /// <summary>
    /// Reads a header from raw bytes; ICF bit 7 chooses the short or the long form.
    /// </summary>
    /// <param name="source">The bytes, starting at ICF.</param>
    /// <param name="responseWait">The wait time that preceded the header (0 for a response).</param>
    /// <param name="header">The header read.</param>
    /// <returns>False when <paramref name="source"/> is too short for the form ICF announces.</returns>
    public static bool TryRead(ReadOnlySpan<byte> source, int responseWait, out FinsHeader header)
    {
        header = default;
        if (source.IsEmpty || (uint)responseWait > MaxResponseWait)
        {
            return false;
        }

        byte icf = source[0];
        if ((icf & 0x80) == 0)
        {
            if (source.Length < DirectLength)
            {
                return false;
            }

            header = new FinsHeader(responseWait, icf, 0, 0, 0, 0, source[1], 0, 0, source[2], source[3]);
            return true;
        }

        if (source.Length < NetworkLength)
        {
            return false;
        }

        header = new FinsHeader(responseWait, icf, source[1], source[2], source[3], source[4], source[5], source[6], source[7], source[8], source[9]);
        return true;
    }

    /// <inheritdoc/>
    public bool Equals(FinsHeader other)
        => ResponseWait == other.ResponseWait && Icf == other.Icf && Rsv == other.Rsv && Gct == other.Gct
            && Dna == other.Dna && Da1 == other.Da1 && Da2 == other.Da2 && Sna == other.Sna && Sa1 == other.Sa1
            && Sa2 == other.Sa2 && Sid == other.Sid;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is FinsHeader other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode()
        => (ResponseWait << 24) ^ (Icf << 16) ^ (Sid << 8) ^ Da2 ^ (Dna << 4) ^ (Da1 << 12) ^ (Sna << 20) ^ (Sa1 << 28) ^ Sa2 ^ Gct ^ Rsv;

    /// <summary>The header in the manuals' notation.</summary>
    public override string ToString()
        => IsNetwork
            ? $"ICF {Icf:X2} RSV {Rsv:X2} GCT {Gct:X2} DNA {Dna:X2} DA1 {Da1:X2} DA2 {Da2:X2} SNA {Sna:X2} SA1 {Sa1:X2} SA2 {Sa2:X2} SID {Sid:X2} wait {ResponseWait}"
            : $"ICF {Icf:X2} DA2 {Da2:X2} SA2 {Sa2:X2} SID {Sid:X2} wait {ResponseWait}";

    /// <summary>Equality.</summary>
    public static bool operator ==(FinsHeader left, FinsHeader right) => left.Equals(right);

    /// <summary>Inequality.</summary>
    public static bool operator !=(FinsHeader left, FinsHeader right) => !left.Equals(right);

    private static void CheckWait(int responseWait)
    {
        if ((uint)responseWait > MaxResponseWait)
        {
            throw new ArgumentOutOfRangeException(nameof(responseWait), responseWait, $"The Host Link response wait time must be 0-{MaxResponseWait} (× 10 ms); it was {responseWait}.");
        }
    }
}
