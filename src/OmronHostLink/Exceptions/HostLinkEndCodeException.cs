namespace OmronHostLink;

/// <summary>The PLC answered a C-mode command with an error end code (or with IC: header not recognised).</summary>
public sealed class HostLinkEndCodeException : HostLinkException
{
    /// <summary>Creates the exception for <paramref name="endCode"/> answered to <paramref name="header"/> by unit <paramref name="unit"/>.</summary>
    public HostLinkEndCodeException(EndCode endCode, string header, int unit)
        : base($"Unit {unit:D2} answered {header} with end code {endCode.ToCode()}: {endCode.Meaning()}.")
    {
        EndCode = endCode;
        Header = header;
        Unit = unit;
    }

    /// <summary>The end code.</summary>
    public EndCode EndCode { get; }

    /// <summary>The command header the PLC answered (for example <c>RD</c>).</summary>
    public string Header { get; }

    /// <summary>The unit number that answered.</summary>
    public int Unit { get; }

    /// <summary>The kind of failure, for callers that branch on it.</summary>
    public EndCodeCategory Category => EndCode.Category();

    /// <summary>The meaning of the end code.</summary>
    public string Meaning => EndCode.Meaning();

    /// <inheritdoc/>
    /// <remarks>True for end codes that report a frame the PLC received damaged (<see cref="EndCodes.IsTransient"/>).</remarks>
    public override bool IsTransient => EndCode.IsTransient();
}
