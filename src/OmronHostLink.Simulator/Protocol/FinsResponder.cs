using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Simulator.Protocol;

/// <summary>
/// Executes FINS commands carried over Host Link (header <c>FA</c>) against a <see cref="VirtualPlc"/>: each command
/// its FINS command table executes (0101–0105, 0401, 0402, 0501, 0601, 0620, 0701, 0702, 2101, 2102, 2301, 2302 in the
/// standard table; each row executes its command against the PLC). Any other command code is answered 0401
/// (undefined command).
/// </summary>
/// <remarks>
/// Unlike C-mode, FINS memory writes are allowed in RUN mode; forcing is refused in RUN mode (2206), as C-mode's KS/KR
/// are. Every response code carries the CPU error flags: bit 7 when the first error word (<see cref="VirtualPlc.Errors"/>,
/// the fatal errors) is non-zero, bit 6 for the second (non-fatal).
/// </remarks>
public sealed class FinsResponder
{
    private readonly VirtualPlc _plc;

    /// <summary>Creates a responder for <paramref name="plc"/>.</summary>
    /// <param name="plc">The PLC whose memory and state the commands use.</param>
    public FinsResponder(VirtualPlc plc)
        : this(plc, FinsCommandTable.Standard)
    {
    }

    /// <summary>Creates a responder that executes the commands of <paramref name="table"/>.</summary>
    internal FinsResponder(VirtualPlc plc, FinsCommandTable table)
    {
        ArgumentNullException.ThrowIfNull(plc);
        ArgumentNullException.ThrowIfNull(table);
        _plc = plc;
        Table = table;
    }

    /// <summary>The FINS commands this PLC executes.</summary>
    internal FinsCommandTable Table { get; }

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
            FinsCommand command = message.ToCommand(Table);
            lock (_plc.SyncRoot)
            {
                (code, data) = command.Row.Execute is { } execute ? execute(command, _plc) : FinsReply.Code(FinsEndCodes.UndefinedCommand);
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
}
