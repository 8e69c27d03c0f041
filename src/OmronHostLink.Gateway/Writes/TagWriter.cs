using System.Text.Json;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Writes;

/// <summary>
/// The one path of every write from outside (MQTT JSON commands, Sparkplug B DCMD): the allowlist (only tags configured
/// <c>Writable</c>), the value checked and laid out for the tag's type (<see cref="WriteValueParser"/>), and the write
/// itself through the client its link polls with (the link's one owner of the wire). Nothing reaches the PLC for a
/// value or tag this refuses.
/// </summary>
/// <param name="links">The clients of the links being polled.</param>
internal sealed class TagWriter(OpenLinks links)
{
    /// <summary>Writes <paramref name="value"/> (JSON) to <paramref name="tag"/>, or to one of its values.</summary>
    /// <param name="tag">The tag, as the catalogue knows it.</param>
    /// <param name="value">The JSON value: as for <see cref="WriteValueParser.TryEncode"/>, one value when <paramref name="element"/> is given.</param>
    /// <param name="element">Which value of a tag of several to write (0-based); null for the whole tag.</param>
    /// <param name="cancellationToken">Cancels the write.</param>
    public async Task<TagWriteOutcome> WriteAsync(TagDefinition tag, JsonElement value, int? element, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(tag);
        if (!tag.Writable)
        {
            return TagWriteOutcome.Refused($"{tag.Link}/{tag.Unit}/{tag.Name} is not writable; only tags with Writable: true (HostLink:Links:{tag.Link}:Groups:{tag.Name}:Writable) take writes.");
        }

        if (WritableRule.Problem(tag.Address, tag.Type, tag.Count, tag.CommandSet) is { } notWritable)
        {
            // Refused at start too; checked again here so that no write of such a tag can reach the wire.
            return TagWriteOutcome.Refused($"{tag.Link}/{tag.Unit}/{tag.Name}: {notWritable}");
        }

        PlcAddress address = tag.Address;
        int count = tag.Count;
        if (element is { } index)
        {
            if (tag.Type is PlcValueType.String or PlcValueType.Bit || index < 0 || index >= tag.Count)
            {
                return TagWriteOutcome.Refused($"{tag.Link}/{tag.Unit}/{tag.Name} has no value {index} to write on its own.");
            }

            address = tag.Address.AsWord().Offset(index * tag.Type.WordsPerValue());
            count = 1;
        }

        if (!WriteValueParser.TryEncode(tag.Type, count, value, tag.WordOrder, out ushort[] words, out string why))
        {
            return TagWriteOutcome.Refused($"{address} ({tag.Type.Name()}): {why}");
        }

        HostLinkUnit? client = links.ClientOf(tag.Link);
        if (client is null)
        {
            return TagWriteOutcome.Refused($"link {tag.Link} is not being polled (stopping, or it could not be set up).");
        }

        try
        {
            if (tag.Type == PlcValueType.Bit)
            {
                // A bit is written on its own with FINS 0102 whatever the link's command set (C-mode has no bit write).
                await client.Unit(tag.Unit, HostLinkCommandSet.Fins).WriteBitAsync(address, words[0] != 0, cancellationToken).ConfigureAwait(false);
            }
            else
            {
                await client.Unit(tag.Unit).WriteWordsAsync(address.AsWord(), words, cancellationToken).ConfigureAwait(false);
            }

            return new TagWriteOutcome(TagWriteStatus.Done);
        }
        catch (HostLinkEndCodeException e)
        {
            return new TagWriteOutcome(TagWriteStatus.Failed, e.Message, e.EndCode.ToCode());
        }
        catch (FinsEndCodeException e)
        {
            return new TagWriteOutcome(TagWriteStatus.Failed, e.Message, e.EndCode.ToString());
        }
        catch (ArgumentException e)
        {
            // The library refused it before the wire.
            return TagWriteOutcome.Refused($"{address}: {ErrorText.Of(e)}");
        }
        catch (Exception e) when (e is HostLinkException or ObjectDisposedException)
        {
            return new TagWriteOutcome(TagWriteStatus.Failed, e.Message);
        }
    }
}
