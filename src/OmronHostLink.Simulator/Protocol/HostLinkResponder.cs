using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Simulator.Protocol;

/// <summary>
/// Executes one complete C-mode command (all its frames joined) against a <see cref="VirtualPlc"/> and returns the
/// answer, as a CS/CJ CPU Unit does: every command its <see cref="CModeCommandTable"/> executes (each row parses and
/// executes its command against the PLC), FINS over Host Link (FA, through <see cref="FinsResponder"/>), IC for any
/// other header, 14 and 15 for format and range errors.
/// Frame-level checks (FCS, frame length, the CR handshake of multi-frame exchanges) belong to the caller.
/// </summary>
public sealed class HostLinkResponder
{
    /// <summary>Characters an answer keeps in its first frame: <c>@</c>, unit, header, end code.</summary>
    public const int ResponseFixedLength = CModeResponse.PrefixLength + CModeResponse.EndCodeLength;

    /// <summary>Completion flags an RG answer carries in each frame after the first.</summary>
    public const int MaxFlagsPerLaterFrame = AreaReadCommand.MaxFlagsPerLaterFrame;

    private static readonly PlcModelProfile CsCj = PlcModelProfile.Parse("CS1");

    private readonly VirtualPlc _plc;
    private readonly FinsResponder _fins;

    /// <summary>Creates a responder for <paramref name="plc"/>.</summary>
    /// <param name="plc">The PLC whose memory and state the commands use.</param>
    public HostLinkResponder(VirtualPlc plc)
        : this(plc, CModeCommandTable.Standard)
    {
    }

    /// <summary>Creates a responder that executes the commands of <paramref name="table"/> and <paramref name="fins"/> (default: the standard FINS table).</summary>
    internal HostLinkResponder(VirtualPlc plc, CModeCommandTable table, FinsCommandTable? fins = null)
    {
        ArgumentNullException.ThrowIfNull(plc);
        ArgumentNullException.ThrowIfNull(table);
        _plc = plc;
        _fins = new FinsResponder(plc, fins ?? FinsCommandTable.Standard);
        Table = table;
    }

    /// <summary>The C-mode commands this PLC executes.</summary>
    internal CModeCommandTable Table { get; }

    /// <summary>An answer carrying only an end code (error answers carry no text).</summary>
    /// <param name="unit">The unit number 0-31.</param>
    /// <param name="header">The header echoed.</param>
    /// <param name="code">The end code; <see cref="EndCode.UndefinedHeader"/> gives the IC answer.</param>
    /// <returns>The answer.</returns>
    public static SimResponse EndCodeOnly(int unit, ReadOnlySpan<byte> header, EndCode code)
        => EndCodeOnly(unit, header, code, null);

    /// <summary>An answer carrying only an end code, after the sub-header of a command that has one (QQMR, QQIR).</summary>
    internal static SimResponse EndCodeOnly(int unit, ReadOnlySpan<byte> header, EndCode code, string? subHeader)
    {
        if (subHeader is not null && code != EndCode.UndefinedHeader)
        {
            CModeReply reply = CModeReply.EndCodeOnly(code, subHeader);
            var text = new byte[CModeCommand.PrefixLength + reply.Text.Length];
            CModeResponse.WriteMessageWithoutEndCode(text, unit, Encoding.ASCII.GetString(header), reply.Text);
            return new SimResponse(text, text.Length, 1);
        }

        if (code == EndCode.UndefinedHeader)
        {
            var ic = new byte[CModeCommand.PrefixLength];
            CModeResponse.WriteMessageWithoutEndCode(ic, unit, CModeCommands.UndefinedCommand.Header, default);
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
        if (message.Length < CModeCommand.PrefixLength || !MessagePrefix.TryReadUnit(message, out int unit) || !HostLinkRules.IsUnitNumber(unit))
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
        if (HostLinkRules.CheckUnitNumber(unit) is { } unitProblem)
        {
            throw new ArgumentOutOfRangeException(nameof(unit), unit, $"The unit: {unitProblem}.");
        }

        if (header.Length != 2)
        {
            throw new ArgumentException("A header has two characters.", nameof(header));
        }

        if ((_plc.Model is { } model && !Accepts(model, header)) || Refuses(header))
        {
            return EndCodeOnly(unit, header, EndCode.UndefinedHeader);
        }

        if (CModeHeaders.Is(header, CModeCommands.Fins.Header))
        {
            return _fins.Respond(unit, text);
        }

        CModeCommandRow? row = Table.Find(header, text);
        if (row is null || !row.IsExecutable || !row.IsCommand)
        {
            return EndCodeOnly(unit, header, EndCode.UndefinedHeader);
        }

        CModeCommand command;
        try
        {
            command = CModeCommandParser.Parse(Table, header, text);
        }
        catch (CModeCommandRejectedException e)
        {
            return Reply(unit, row, CModeReply.EndCodeOnly(e.EndCode, row.SubHeader));
        }
        catch (ArgumentException)
        {
            return Reply(unit, row, CModeReply.EndCodeOnly(EndCode.FormatError, row.SubHeader));
        }

        // Without a model the PLC is a CS/CJ CPU: its profile's limits (A0–A447 read-only) hold.
        if (Refusal(_plc.Model ?? CsCj, command) is { } refusal)
        {
            return refusal == EndCode.UndefinedHeader
                ? EndCodeOnly(unit, header, refusal)
                : Reply(unit, row, CModeReply.EndCodeOnly(refusal, row.SubHeader));
        }

        SimResponse? response;
        lock (_plc.SyncRoot)
        {
            response = Reply(unit, row, row.Execute!(command, _plc, unit));
        }

        return _plc.Options.HostLinkCompatibleMode is { } compatible && response is not null
            ? CompatibleModeAnswer.Frame(response, row.Header, CompatibleModeFraming.Of(compatible))
            : response;
    }

    private bool Refuses(ReadOnlySpan<byte> header)
    {
        foreach (string refused in _plc.Options.RefusedCommands)
        {
            if (CModeHeaders.Is(header, refused.ToUpperInvariant()))
            {
                return true;
            }
        }

        return false;
    }

    // FA only with FINS; the rest from the model's C-mode list (TS is answered by every model).
    private static bool Accepts(PlcModelProfile model, ReadOnlySpan<byte> header)
    {
        if (CModeHeaders.Is(header, CModeCommands.Fins.Header))
        {
            return model.SupportsFins;
        }

        return CModeHeaders.Is(header, CModeCommands.Test.Header) || model.AcceptsCMode(HeaderString(header));
    }

    // What the emulated model refuses of a command it has: memory it lacks (15, the manuals' "entry number data error"),
    // and MM where no manual gives its code (IC: the simulator does not invent one).
    private static EndCode? Refusal(PlcModelProfile model, CModeCommand command) => command switch
    {
        AreaReadCommand read when !ModelHas(model, read.Area, read.Begin, read.Count, read.Bank, forWrite: false) => EndCode.EntryNumberDataError,
        AreaWriteCommand write when !ModelHas(model, write.Area, write.Begin, write.Words.Length, write.Bank, forWrite: true) => EndCode.EntryNumberDataError,
        _ when command.Row == CModeCommands.ModelRead && model.ModelCode is null => EndCode.UndefinedHeader,
        _ => null,
    };

    // Every entry is memory the model has (or, for a read, memory its manual says reads 0000) and, for a write, may be written.
    private static bool ModelHas(PlcModelProfile model, CModeArea area, int begin, int count, int bank, bool forWrite)
    {
        for (int entry = begin; entry < begin + count; entry++)
        {
            (PlcArea plcArea, int word) = ModelAddress(model, area, entry);
            PlcAreaRange? range = model.Find(plcArea, word, bank);
            if (range is null ? forWrite || !model.ReadsZero(plcArea, word, bank) : forWrite && !range.Writable)
            {
                return false;
            }
        }

        return true;
    }

    // A C-mode entry as the model's profile names it: LR stays LR, and on a shared TC space every entry is a timer number.
    private static (PlcArea Area, int Word) ModelAddress(PlcModelProfile model, CModeArea area, int entry) => area switch
    {
        CModeArea.Lr => (PlcArea.Link, entry),
        CModeArea.TimerCounterPv or CModeArea.TimerCounterStatus when model.SharesTimerCounterNumbers => (PlcArea.Timer, entry),
        _ => CModeAddressing.Locate(area, entry),
    };

    private static string HeaderString(ReadOnlySpan<byte> header) => Encoding.ASCII.GetString(header);

    /// <summary>Frames a row's reply: <c>@</c>, unit, header, then its text; null for no answer.</summary>
    private static SimResponse? Reply(int unit, CModeCommandRow row, CModeReply? reply)
    {
        if (reply is null)
        {
            return null;
        }

        if (reply.IsUndefined)
        {
            return EndCodeOnly(unit, Encoding.ASCII.GetBytes(row.Header), EndCode.UndefinedHeader);
        }

        var message = new byte[CModeCommand.PrefixLength + reply.Text.Length];
        CModeResponse.WriteMessageWithoutEndCode(message, unit, row.Header, reply.Text);
        return new SimResponse(message, CModeCommand.PrefixLength + reply.FixedText, reply.AtomLength, reply.MaxContinuationText);
    }
}
