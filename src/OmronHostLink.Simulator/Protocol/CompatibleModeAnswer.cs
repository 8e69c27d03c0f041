using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Simulator.Protocol;

/// <summary>
/// An answer as a Serial Communications Unit in a Host Link-compatible mode sends it (W336 4-6-2): area reads cut into
/// the frames the mode uses, and MS with the 16 message characters as spaces where the mode always sends them.
/// </summary>
internal static class CompatibleModeAnswer
{
    // End code + MS status word: an MS answer without message characters.
    private const int StatusOnlyText = CModeResponse.EndCodeLength + 4;

    public static SimResponse Frame(SimResponse answer, string header, CompatibleModeFraming framing)
    {
        if (header == CModeCommands.StatusRead.Header)
        {
            return framing.StatusMessageAlwaysSent == true && answer.Message.Length == CModeResponse.PrefixLength + StatusOnlyText
                ? new SimResponse([.. answer.Message, .. Spaces], answer.FixedLength, answer.AtomLength, answer.MaxContinuationText)
                : answer;
        }

        (int first, int entry) = framing.FrameCapacity(header, first: true);
        if (first == 0 || answer.AtomLength != entry)
        {
            return answer; // not an area read, or an answer carrying only an end code
        }

        (int later, _) = framing.FrameCapacity(header, first: false);
        return new SimResponse(answer.Message, answer.FixedLength, answer.AtomLength, later) { MaxFirstText = first };
    }

    private static readonly byte[] Spaces = [.. System.Linq.Enumerable.Repeat((byte)' ', 16)];
}
