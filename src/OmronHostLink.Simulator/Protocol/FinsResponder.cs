using System.Buffers.Binary;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Simulator.Protocol;

/// <summary>
/// Executes FINS commands carried over Host Link (header <c>FA</c>) against a <see cref="VirtualPlc"/>: 0101 MEMORY
/// AREA READ, 0102 WRITE, 0103 FILL, 0104 MULTIPLE READ, 0105 TRANSFER, 0401 RUN, 0402 STOP, 0501 CPU UNIT DATA
/// READ, 0601 CPU UNIT STATUS READ, 0620 CYCLE TIME READ, 0701/0702 CLOCK READ/WRITE, 2101 ERROR CLEAR, 2102 ERROR LOG
/// READ, 2301/2302 FORCED SET/RESET (CANCEL). Any other command code is answered 0401 (undefined command).
/// </summary>
/// <remarks>
/// <para>Areas: CIO/W/H/A words (B0–B3) and bits (30–33), DM (82/02), timer/counter PVs (89; counter n at 0x8000 + n)
/// and completion flags (09), EM banks 0–C (A0–AC/20–2C) and the current bank (98/0A, always bank 0). Forced-status
/// areas, task flags and registers are answered 1101 (area missing).</para>
/// <para>Unlike C-mode, FINS memory writes are allowed in RUN mode; A0–A447 are read-only (2101). Forcing is refused in
/// RUN mode (2206), as C-mode's KS/KR are. Every response code carries the CPU error flags: bit 7 when the first
/// error word (<see cref="VirtualPlc.Errors"/>, the fatal errors) is non-zero, bit 6 for the second (non-fatal).</para>
/// </remarks>
public sealed class FinsResponder
{
    private readonly VirtualPlc _plc;

    /// <summary>Creates a responder for <paramref name="plc"/>.</summary>
    /// <param name="plc">The PLC whose memory and state the commands use.</param>
    public FinsResponder(VirtualPlc plc)
    {
        ArgumentNullException.ThrowIfNull(plc);
        _plc = plc;
    }

    /// <summary>The model name 0501 reports.</summary>
    public string CpuModel { get; init; } = "CJ1M-CPU13";

    /// <summary>The version 0501 reports.</summary>
    public string CpuVersion { get; init; } = "OmronHostLink.Sim";

    /// <summary>Executes the FINS command in the text after <c>FA</c> of a validated frame.</summary>
    /// <param name="unit">The Host Link unit the frame was addressed to (echoed).</param>
    /// <param name="text">The characters between <c>FA</c> and the FCS: wait time, FINS header, MRC SRC, parameters.</param>
    /// <returns>The answer: a FINS response, or <c>@uuFA14</c> when the FINS part cannot be read at all.</returns>
    public SimResponse Respond(int unit, ReadOnlySpan<byte> text)
    {
        FinsCommandMessage message;
        try
        {
            message = FinsMessage.ParseCommand(text, unit);
        }
        catch (HostLinkFrameException)
        {
            var error = new byte[FinsMessage.HostLinkErrorLength];
            FinsMessage.WriteHostLinkError(error, unit, EndCode.FormatError);
            return new SimResponse(error, error.Length, 1) { IsUnsplit = true };
        }

        ushort code;
        byte[] data = [];
        try
        {
            FinsCommand command = message.ToCommand();
            lock (_plc.SyncRoot)
            {
                code = Execute(command, out data);
            }
        }
        catch (FinsFormatException e)
        {
            code = e.EndCode.Raw;
        }

        PlcErrorInfo errors = _plc.Errors;
        code |= (ushort)((errors.FirstWord != 0 ? FinsEndCode.FatalCpuErrorFlag : 0) | (errors.SecondWord != 0 ? FinsEndCode.NonFatalCpuErrorFlag : 0));
        var response = new byte[FinsMessage.GetResponseLength(message.Header, data.Length)];
        FinsMessage.WriteResponse(response, unit, message.Header, message.CommandCode, new FinsEndCode(code), data);
        return new SimResponse(response, response.Length, 1) { IsUnsplit = true, Delay = message.Header.ResponseWaitTime };
    }

    private static FinsCpuMode ToFins(PlcMode mode) => mode switch
    {
        PlcMode.Program => FinsCpuMode.Program,
        PlcMode.Monitor => FinsCpuMode.Monitor,
        _ => FinsCpuMode.Run,
    };

    /// <summary>Where element <paramref name="index"/> from <paramref name="address"/> lies in the simulator's memory.</summary>
    private static bool TryLocate(FinsMemoryAddress address, int index, out Location location)
    {
        location = default;
        byte code = address.AreaCode;
        bool bitArea = FinsMemoryArea.IsBitArea(code);
        int word = address.Word;
        int bit = -1;
        if (bitArea && code != FinsMemoryArea.TimerCounterFlag)
        {
            int b = address.Bit + index;
            word += b / 16;
            bit = b % 16;
        }
        else
        {
            // The bit field of a word address is ignored: a published capture reads HR words with bit field 0D
            // and gets normal completion.
            word += index;
        }

        // The simulator's current EM bank is always bank 0.
        if (!FinsAddressing.TryLocate(code, word, currentEmBank: 0, out PlcArea area, out word, out int bank))
        {
            return false;
        }

        bool flag = code == FinsMemoryArea.TimerCounterFlag;
        if (flag && address.Bit != 0)
        {
            return false;
        }

        location = new Location(area, word, flag ? -1 : bit, bank, Flag: flag);
        return word < PlcAddress.AreaSize(area);
    }

    private static ushort CheckArea(FinsMemoryAddress address, int count, bool write)
    {
        if (!IsSupported(address.AreaCode))
        {
            return FinsEndCodes.AreaClassificationMissing;
        }

        if (count == 0)
        {
            return FinsEndCodes.NormalCompletion;
        }

        if (!TryLocate(address, 0, out Location first) || !TryLocate(address, count - 1, out Location last)
            || first.Area != last.Area)
        {
            return FinsEndCodes.AddressRangeError;
        }

        if (write && first.Area == PlcArea.Auxiliary && first.Word < PlcAreaInfo.FirstWritableAuxiliaryWord)
        {
            return FinsEndCodes.WriteNotPossibleReadOnly;
        }

        return FinsEndCodes.NormalCompletion;
    }

    private static bool IsSupported(byte code) => FinsAddressing.TryLocate(code, 0, 0, out _, out _, out _);

    private ushort Execute(FinsCommand command, out byte[] data)
    {
        data = [];
        switch (command)
        {
            case MemoryAreaReadCommand read:
            {
                ushort check = CheckArea(read.Address, read.Count, write: false);
                if (check == FinsEndCodes.NormalCompletion)
                {
                    data = ReadElements(read.Address, read.Count);
                }

                return check;
            }

            case MemoryAreaWriteCommand write:
            {
                ushort check = CheckArea(write.Address, write.Count, write: true);
                if (check == FinsEndCodes.NormalCompletion)
                {
                    WriteElements(write.Address, write.Count, write.Data.Span);
                }

                return check;
            }

            case MemoryAreaFillCommand fill:
            {
                ushort check = CheckArea(fill.Address, fill.Count, write: true);
                if (check != FinsEndCodes.NormalCompletion)
                {
                    return check;
                }

                int size = fill.Address.ElementSize;
                var bytes = new byte[fill.Count * size];
                for (int i = 0; i < fill.Count; i++)
                {
                    if (size == 2)
                    {
                        BinaryPrimitives.WriteUInt16BigEndian(bytes.AsSpan(i * 2), fill.Value);
                    }
                    else
                    {
                        bytes[i] = fill.Value != 0 ? (byte)1 : (byte)0;
                    }
                }

                WriteElements(fill.Address, fill.Count, bytes);
                return FinsEndCodes.NormalCompletion;
            }

            case MultipleMemoryAreaReadCommand multiple:
            {
                using var result = new MemoryStream();
                foreach (FinsMemoryAddress item in multiple.Items)
                {
                    ushort check = CheckArea(item, 1, write: false);
                    if (check != FinsEndCodes.NormalCompletion)
                    {
                        return check;
                    }

                    result.WriteByte(item.AreaCode);
                    result.Write(ReadElements(item, 1));
                }

                data = result.ToArray();
                return FinsEndCodes.NormalCompletion;
            }

            case MemoryAreaTransferCommand transfer:
            {
                if (FinsMemoryArea.ElementSize(transfer.Source.AreaCode) != 2 || FinsMemoryArea.ElementSize(transfer.Destination.AreaCode) != 2)
                {
                    return FinsEndCodes.AreaClassificationMissing;
                }

                ushort check = CheckArea(transfer.Source, transfer.Count, write: false);
                check = check != FinsEndCodes.NormalCompletion ? check : CheckArea(transfer.Destination, transfer.Count, write: true);
                if (check == FinsEndCodes.NormalCompletion && transfer.Count > 0)
                {
                    WriteElements(transfer.Destination, transfer.Count, ReadElements(transfer.Source, transfer.Count));
                }

                return check;
            }

            case RunCommand run:
                // [unverified] With no mode given the CPU Unit goes to MONITOR mode.
                _plc.Mode = run.Mode == FinsCpuMode.Run ? PlcMode.Run : PlcMode.Monitor;
                return FinsEndCodes.NormalCompletion;
            case StopCommand:
                _plc.Mode = PlcMode.Program;
                return FinsEndCodes.NormalCompletion;
            case CpuUnitDataReadCommand:
            {
                var unitData = new FinsCpuUnitData(CpuModel, CpuVersion);
                data = new byte[unitData.Length];
                unitData.Write(data);
                return FinsEndCodes.NormalCompletion;
            }

            case CpuUnitStatusReadCommand:
            {
                PlcErrorInfo errors = _plc.Errors;
                string? message = _plc.FalMessage;
                var status = new FinsCpuStatus(
                    _plc.Mode == PlcMode.Program ? (byte)0x00 : (byte)0x01,
                    ToFins(_plc.Mode),
                    errors.FirstWord,
                    errors.SecondWord,
                    message is null ? (ushort)0 : (ushort)0x0001,
                    0,
                    message ?? string.Empty);
                data = new byte[FinsCpuStatus.Length];
                status.Write(data);
                return FinsEndCodes.NormalCompletion;
            }

            case CycleTimeReadCommand:
            {
                // 1.0 ms average, 1.5 ms maximum, 0.8 ms minimum, in 0.1 ms units.
                var cycle = new FinsCycleTime(10, 15, 8);
                data = new byte[FinsCycleTime.Length];
                cycle.Write(data);
                return FinsEndCodes.NormalCompletion;
            }

            case ClockReadCommand:
            {
                var clock = new FinsClock(_plc.Clock);
                data = new byte[FinsClock.Length];
                clock.Write(data);
                return FinsEndCodes.NormalCompletion;
            }

            case ClockWriteCommand clockWrite:
            {
                DateTime now = _plc.Clock;
                _plc.Clock = clockWrite.IncludesSecond ? clockWrite.Time : clockWrite.Time.AddSeconds(now.Second);
                return FinsEndCodes.NormalCompletion;
            }

            case ErrorClearCommand:
                _plc.ClearErrors();
                return FinsEndCodes.NormalCompletion;
            case ErrorLogReadCommand:
            {
                var log = new FinsErrorLog(20, 0, []);
                data = new byte[log.Length];
                log.Write(data);
                return FinsEndCodes.NormalCompletion;
            }

            case ForcedSetResetCommand force:
                return Force(force);
            case ForcedSetResetCancelCommand:
                if (_plc.Mode == PlcMode.Run)
                {
                    return FinsEndCodes.NotExecutableInRunMode;
                }

                _plc.ReleaseAllForced();
                return FinsEndCodes.NormalCompletion;
            default:
                return FinsEndCodes.UndefinedCommand;
        }
    }

    private ushort Force(ForcedSetResetCommand force)
    {
        if (_plc.Mode == PlcMode.Run)
        {
            return FinsEndCodes.NotExecutableInRunMode;
        }

        var targets = new List<(FinsForceAction Action, Location Where)>();
        foreach (FinsForcedBit item in force.Items)
        {
            byte code = item.Address.AreaCode;
            if (code is not (FinsMemoryArea.CioBit or FinsMemoryArea.WorkBit or FinsMemoryArea.HoldingBit or FinsMemoryArea.TimerCounterFlag))
            {
                return FinsEndCodes.AreaClassificationMissing;
            }

            if (!TryLocate(item.Address, 0, out Location where))
            {
                return FinsEndCodes.AddressRangeError;
            }

            targets.Add((item.Action, where));
        }

        foreach ((FinsForceAction action, Location where) in targets)
        {
            int bit = where.Flag ? 0 : where.Bit;
            switch (action)
            {
                case FinsForceAction.ForceSet or FinsForceAction.ForceReset:
                    _plc.ForceBit(where.Area, where.Word, bit, action == FinsForceAction.ForceSet);
                    break;
                case FinsForceAction.ReleaseToOn or FinsForceAction.ReleaseToOff:
                    _plc.ReleaseForced(where.Area, where.Word, bit);
                    SetElement(where, action == FinsForceAction.ReleaseToOn);
                    break;
                default:
                    _plc.ReleaseForced(where.Area, where.Word, bit);
                    break;
            }
        }

        return FinsEndCodes.NormalCompletion;
    }

    private void SetElement(Location where, bool value)
    {
        if (where.Flag)
        {
            _plc.SetFlag(where.Area, where.Word, value);
        }
        else
        {
            _plc.SetBit(where.Area, where.Word, where.Bit, value, where.Bank);
        }
    }

    private byte[] ReadElements(FinsMemoryAddress address, int count)
    {
        int size = address.ElementSize;
        var bytes = new byte[count * size];
        for (int i = 0; i < count; i++)
        {
            TryLocate(address, i, out Location where);
            if (where.Flag)
            {
                bytes[i] = _plc.GetFlag(where.Area, where.Word) ? (byte)1 : (byte)0;
            }
            else if (where.Bit >= 0)
            {
                bytes[i] = _plc.GetBit(where.Area, where.Word, where.Bit, where.Bank) ? (byte)1 : (byte)0;
            }
            else
            {
                BinaryPrimitives.WriteUInt16BigEndian(bytes.AsSpan(i * 2), _plc.ReadWord(where.Area, where.Word, where.Bank));
            }
        }

        return bytes;
    }

    private void WriteElements(FinsMemoryAddress address, int count, ReadOnlySpan<byte> data)
    {
        for (int i = 0; i < count; i++)
        {
            TryLocate(address, i, out Location where);
            if (where.Flag || where.Bit >= 0)
            {
                SetElement(where, data[i] != 0);
            }
            else
            {
                _plc.WriteWord(where.Area, where.Word, BinaryPrimitives.ReadUInt16BigEndian(data.Slice(i * 2)), where.Bank);
            }
        }
    }

    /// <summary>One element of simulator memory: a word, a bit of a word (<see cref="Bit"/> ≥ 0) or a completion flag.</summary>
    private readonly record struct Location(PlcArea Area, int Word, int Bit, int Bank, bool Flag);
}
