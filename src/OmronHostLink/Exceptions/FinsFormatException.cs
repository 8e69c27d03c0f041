using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>
/// A FINS command's parameters are not what the command requires (too long, too short, an unknown memory area, an
/// address out of range...). <see cref="EndCode"/> is the FINS response code a PLC answers such a command with, so a
/// simulator can reply with it.
/// </summary>
internal sealed class FinsFormatException : HostLinkException
{
    /// <summary>Creates the exception.</summary>
    /// <param name="endCode">The FINS response code that reports the problem (for example <c>1002</c>, command too short).</param>
    /// <param name="message">What is wrong, in the user's words.</param>
    public FinsFormatException(ushort endCode, string message)
        : base(message)
    {
        EndCode = new FinsEndCode(endCode);
    }

    /// <summary>The FINS response code that answers the faulty command.</summary>
    public FinsEndCode EndCode { get; }
}
