using OmronHostLink.Link;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>Raw exchanges for diagnostic tools (the console's <c>raw</c> command).</summary>
public partial class HostLinkUnit
{
    /// <summary>The most response text a raw exchange accepts (every frame's text joined).</summary>
    internal const int MaxRawResponseText = 64 * 1024;

    /// <summary>
    /// Sends <c>@</c> + unit + <paramref name="text"/> (header and command text, unframed) as one frame and returns the
    /// answer's text after the header, every frame joined, uninterpreted: end codes are not checked. The answer must
    /// echo the header (an IC answer raises <see cref="HostLinkEndCodeException"/>). Never retried: the command may write.
    /// </summary>
    /// <param name="text">Header (2 characters) and command text; printable ASCII without <c>*</c>, <c>@</c> or CR.</param>
    /// <param name="expectsResponse">False for commands the PLC does not answer (XZ).</param>
    /// <param name="cancellationToken">Cancels the exchange.</param>
    /// <exception cref="ArgumentException">The text is shorter than a header, cannot travel in a frame, or does not fit one frame.</exception>
    internal ValueTask<byte[]> ExchangeRawAsync(string text, bool expectsResponse, CancellationToken cancellationToken = default)
    {
        byte[] body = SafeText.ToAscii(text, nameof(text));
        if (body.Length < 2)
        {
            throw new ArgumentException("A raw command needs at least a two-character header.", nameof(text));
        }

        var message = new byte[MessagePrefix.UnitLength + body.Length];
        MessagePrefix.WriteUnit(message, UnitNumber);
        body.CopyTo(message, MessagePrefix.UnitLength);
        string header = text.Substring(0, 2);
        var shape = ExchangeShape.CMode(
            message.Length,
            atomLength: 1,
            multiFrameCommand: false,
            expectsResponse,
            MaxRawResponseText,
            CModeCommand.AnswerCanEqualCommand(header, body.Length - 2));
        var request = new HostLinkRequest(UnitNumber, header, message, shape);
        return Connection.ExecuteAsync(request, 0, static (answer, _) => answer.ToArray(), 0, cancellationToken);
    }
}
