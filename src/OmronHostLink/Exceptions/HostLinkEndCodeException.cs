namespace OmronHostLink;

/// <summary>The PLC answered a C-mode command with an error end code (or with IC: header not recognised).</summary>
public sealed class HostLinkEndCodeException : EndCodeException
{
    private static readonly Dictionary<EndCode, string> Names = EndCodes.All.ToDictionary(c => c, c => c.ToString());

    /// <summary>Creates the exception for <paramref name="endCode"/> answered to <paramref name="header"/> by unit <paramref name="unit"/>.</summary>
    public HostLinkEndCodeException(EndCode endCode, string header, int unit)
        : base($"Unit {unit:D2} answered {header} with end code {endCode.ToCode()}: {endCode.Meaning()}.", unit)
    {
        EndCode = endCode;
        Header = header;
    }

    /// <summary>The end code.</summary>
    public EndCode EndCode { get; }

    /// <summary>The command header the PLC answered (for example <c>RD</c>).</summary>
    public string Header { get; }

    /// <summary>The kind of failure, for callers that branch on it.</summary>
    public EndCodeCategory Category => EndCode.Category();

    /// <summary>The meaning of the end code.</summary>
    public string Meaning => EndCode.Meaning();

    /// <inheritdoc/>
    /// <remarks>True for end codes that report a frame the PLC received damaged (<see cref="EndCodes.IsTransient"/>).</remarks>
    public override bool IsTransient => EndCode.IsTransient();

    /// <inheritdoc/>
    internal override bool ReportsLineDamage => Category == EndCodeCategory.FrameDamaged;

    /// <inheritdoc/>
    /// <remarks>The code's name (<c>NotExecutableInRunMode</c>), or <c>end_code_</c> and its two characters for one the manuals do not define.</remarks>
    internal override string ErrorType => Names.TryGetValue(EndCode, out string? name) ? name : "end_code_" + EndCode.ToCode();

    /// <inheritdoc/>
    internal override string FrameEndCode => EndCode.ToCode();
}
