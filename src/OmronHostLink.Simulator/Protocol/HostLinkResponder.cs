using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Simulator.Protocol;

/// <summary>
/// Executes one complete C-mode command (all its frames joined) against a <see cref="VirtualPlc"/> and returns the
/// answer, as a CS/CJ CPU Unit does: every command <see cref="CModeCommand.Parse"/> knows, FINS over Host Link (FA,
/// through <see cref="FinsResponder"/>), IC for any other header,
/// end code 01 for area writes and forcing in RUN mode, 14 and 15 for format and range errors, no answer to XZ.
/// Frame-level checks (FCS, frame length, the CR handshake of multi-frame exchanges) belong to the caller.
/// </summary>
public sealed class HostLinkResponder
{
    /// <summary>Characters an answer keeps in its first frame: <c>@</c>, unit, header, end code.</summary>
    public const int ResponseFixedLength = CModeResponse.PrefixLength + CModeResponse.EndCodeLength;

    /// <summary>Completion flags an RG answer carries in each frame after the first.</summary>
    public const int MaxFlagsPerLaterFrame = 124;

    private readonly VirtualPlc _plc;
    private readonly FinsResponder _fins;

    /// <summary>Creates a responder for <paramref name="plc"/>.</summary>
    /// <param name="plc">The PLC whose memory and state the commands use.</param>
    public HostLinkResponder(VirtualPlc plc)
    {
        ArgumentNullException.ThrowIfNull(plc);
        _plc = plc;
        _fins = new FinsResponder(plc);
    }

    /// <summary>An answer carrying only an end code (error answers carry no text).</summary>
    /// <param name="unit">The unit number 0-31.</param>
    /// <param name="header">The header echoed.</param>
    /// <param name="code">The end code; <see cref="EndCode.UndefinedHeader"/> gives the IC answer.</param>
    /// <returns>The answer.</returns>
    public static SimResponse EndCodeOnly(int unit, ReadOnlySpan<byte> header, EndCode code)
    {
        if (code == EndCode.UndefinedHeader)
        {
            var ic = new byte[CModeCommand.PrefixLength];
            CModeResponse.WriteMessageWithoutEndCode(ic, unit, CModeHeaders.UndefinedCommand, default);
            return new SimResponse(ic, CModeCommand.PrefixLength, 1);
        }

        var message = new byte[ResponseFixedLength];
        CModeResponse.WriteMessage(message, unit, HeaderString(header), code, default);
        return new SimResponse(message, ResponseFixedLength, 1);
    }

    /// <summary>Executes a command message <c>@</c> + unit + header + text (FCS and ending already removed).</summary>
    /// <param name="message">The unframed message.</param>
    /// <returns>The answer, or null when the PLC sends none (XZ; a message too short to carry a unit and header).</returns>
    public SimResponse? Respond(ReadOnlySpan<byte> message)
    {
        if (message.Length < CModeCommand.PrefixLength || !MessagePrefix.TryReadUnit(message, out int unit) || unit > HostLinkUnit.MaxUnitNumber)
        {
            return null;
        }

        return Respond(unit, message.Slice(3, 2), message.Slice(CModeCommand.PrefixLength));
    }

    /// <summary>Executes a command for <paramref name="unit"/> with its joined text.</summary>
    /// <param name="unit">The unit number 0-31 (echoed in the answer).</param>
    /// <param name="header">The two header characters.</param>
    /// <param name="text">The command text of every frame, joined.</param>
    /// <returns>The answer, or null when the PLC sends none (XZ).</returns>
    public SimResponse? Respond(int unit, ReadOnlySpan<byte> header, ReadOnlySpan<byte> text)
    {
        if ((uint)unit > HostLinkUnit.MaxUnitNumber)
        {
            throw new ArgumentOutOfRangeException(nameof(unit), unit, $"Unit numbers are 0-{HostLinkUnit.MaxUnitNumber}.");
        }

        if (header.Length != 2)
        {
            throw new ArgumentException("A header has two characters.", nameof(header));
        }

        if (CModeHeaders.Is(header, CModeHeaders.Fins))
        {
            return _fins.Respond(unit, text);
        }

        if (CModeHeaders.Is(header, CModeHeaders.Test))
        {
            // TS echoes its text exactly, without an end code (the text is not checked like a command's).
            if (text.Length > TestCommand.MaxTextLength)
            {
                return EndCodeOnly(unit, header, EndCode.FrameLengthError);
            }

            var echo = new byte[CModeCommand.PrefixLength + text.Length];
            CModeResponse.WriteMessageWithoutEndCode(echo, unit, CModeHeaders.Test, text);
            return new SimResponse(echo, CModeCommand.PrefixLength, 1);
        }

        CModeCommand command;
        try
        {
            command = CModeCommand.Parse(header, text);
        }
        catch (CModeCommandRejectedException e)
        {
            return EndCodeOnly(unit, header, e.EndCode);
        }
        catch (ArgumentException)
        {
            return EndCodeOnly(unit, header, EndCode.FormatError);
        }

        lock (_plc.SyncRoot)
        {
            return Execute(unit, command);
        }
    }

    private static string HeaderString(ReadOnlySpan<byte> header) => Encoding.ASCII.GetString(header);

    private static SimResponse Ok(int unit, string header, ReadOnlySpan<byte> data, int atomLength = 4)
    {
        var message = new byte[ResponseFixedLength + data.Length];
        CModeResponse.WriteMessage(message, unit, header, EndCode.NormalCompletion, data);

        // RG: 121 points in the first frame, 124 in later ones (C200HX RG page), one short of what 128 characters hold.
        bool flags = header == CModeAreaInfo.ReadHeader(CModeArea.TimerCounterStatus);
        return new SimResponse(message, ResponseFixedLength, atomLength, flags ? MaxFlagsPerLaterFrame : 0);
    }

    private SimResponse? Execute(int unit, CModeCommand command)
    {
        switch (command)
        {
            case AreaReadCommand read:
                return Read(unit, read);
            case AreaWriteCommand write:
                if (_plc.Mode == PlcMode.Run)
                {
                    return EndCodeOnly(unit, Encoding.ASCII.GetBytes(write.Header), EndCode.NotExecutableInRunMode);
                }

                for (int i = 0; i < write.Words.Length; i++)
                {
                    (PlcArea area, int word) = CModeAddressing.Locate(write.Area, write.Begin + i);
                    _plc.WriteWord(area, word, write.Words[i], write.Bank);
                }

                return Ok(unit, write.Header, default);
            case StatusReadCommand:
            {
                string? message = _plc.FalMessage;
                Span<byte> data = stackalloc byte[message is null ? 4 : 20];
                HexAscii.WriteWord(CModeResponse.StatusWord(_plc.Mode, _plc.StatusLowByte), data);
                if (message is not null)
                {
                    data.Slice(4).Fill((byte)' ');
                    Encoding.ASCII.GetBytes(message, data.Slice(4));
                }

                return Ok(unit, CModeHeaders.StatusRead, data, 1);
            }

            case StatusChangeCommand change:
                _plc.Mode = change.Mode;
                return Ok(unit, CModeHeaders.StatusChange, default);
            case ErrorReadCommand errorRead:
            {
                PlcErrorInfo errors = _plc.Errors;
                Span<byte> data = stackalloc byte[8];
                HexAscii.WriteWord(errors.FirstWord, data);
                HexAscii.WriteWord(errors.SecondWord, data.Slice(4));
                if (errorRead.Clear)
                {
                    _plc.ClearErrors();
                }

                return Ok(unit, CModeHeaders.ErrorRead, data);
            }

            case ModelReadCommand:
            {
                Span<byte> data = stackalloc byte[2];
                HexAscii.WriteByte(_plc.ModelCode, data);
                return Ok(unit, CModeHeaders.ModelRead, data, 2);
            }

            case ForceBitCommand force:
            {
                if (_plc.Mode == PlcMode.Run)
                {
                    return EndCodeOnly(unit, Encoding.ASCII.GetBytes(force.Header), EndCode.NotExecutableInRunMode);
                }

                (PlcArea area, int word) = CModeAddressing.Locate(force.Area, force.Word);
                _plc.ForceBit(area, word, force.Bit, force.Set);
                return Ok(unit, force.Header, default);
            }

            case MultipleForceCommand multiple:
                if (_plc.Mode == PlcMode.Run)
                {
                    return EndCodeOnly(unit, Encoding.ASCII.GetBytes(multiple.Header), EndCode.NotExecutableInRunMode);
                }

                MultipleForce(multiple);
                return Ok(unit, CModeHeaders.MultipleForcedSetReset, default);
            case ForcedCancelCommand:
                if (_plc.Mode == PlcMode.Run)
                {
                    return EndCodeOnly(unit, Encoding.ASCII.GetBytes(command.Header), EndCode.NotExecutableInRunMode);
                }

                _plc.ReleaseAllForced();
                return Ok(unit, CModeHeaders.ForcedSetResetCancel, default);
            case AbortCommand:
                return null;
            default:
                return EndCodeOnly(unit, Encoding.ASCII.GetBytes(command.Header), EndCode.UndefinedHeader);
        }
    }

    private SimResponse Read(int unit, AreaReadCommand read)
    {
        int atom = read.ResponseAtomLength;
        var data = new byte[read.Count * atom];
        for (int i = 0; i < read.Count; i++)
        {
            (PlcArea area, int word) = CModeAddressing.Locate(read.Area, read.Begin + i);
            if (read.Area == CModeArea.TimerCounterStatus)
            {
                data[i] = _plc.GetFlag(area, word) ? (byte)'1' : (byte)'0';
            }
            else
            {
                HexAscii.WriteWord(_plc.ReadWord(area, word, read.Bank), data.AsSpan(i * 4, 4));
            }
        }

        return Ok(unit, read.Header, data, atom);
    }

    private void MultipleForce(MultipleForceCommand command)
    {
        (PlcArea area, int word) = CModeAddressing.Locate(command.Area, command.Word);
        bool flag = area is PlcArea.Timer or PlcArea.Counter;
        for (int i = 0; i < 16; i++)
        {
            int bit = 15 - i;
            ForceAction action = command.Actions[i];
            if (flag && bit != 15)
            {
                continue;
            }

            int target = flag ? 0 : bit;
            switch (action)
            {
                case ForceAction.Reset or ForceAction.Set:
                    if (flag)
                    {
                        _plc.SetFlag(area, word, action == ForceAction.Set);
                    }
                    else
                    {
                        _plc.SetBit(area, word, target, action == ForceAction.Set);
                    }

                    break;
                case ForceAction.ForcedReset or ForceAction.ForcedSet:
                    _plc.ForceBit(area, word, target, action == ForceAction.ForcedSet);
                    break;
                case ForceAction.Cancel:
                    _plc.ReleaseForced(area, word, target);
                    break;
            }
        }
    }
}
