using System.Text;

namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// The rows of the standard C-mode table (<see cref="CModeCommandTable.Standard"/>), in the order of W342 section 4,
/// and the commands without text as ready instances. A PLC model profile names the rows its model accepts; the rows of
/// commands with parameters live beside their command types (<see cref="AreaReadCommand.Rows"/>,
/// <see cref="AreaWriteCommand.Rows"/>, <see cref="StatusChangeCommand.CommandRow"/>, …).
/// </summary>
internal static class CModeCommands
{
    /// <summary>MS: STATUS READ: end code, status word (4) and the FAL/FALS message (16) when one is active.</summary>
    public static CModeCommandRow StatusRead { get; } = Simple(
        "MS",
        "STATUS READ",
        CommandEffect.ReadOnly,
        CModeResponse.EndCodeLength + 4 + 16,
        static plc =>
        {
            string? message = plc.FalMessage;
            Span<byte> data = stackalloc byte[message is null ? 4 : 20];
            HexAscii.WriteWord(CModeResponse.StatusWord(plc.Mode, plc.StatusLowByte), data);
            if (message is not null)
            {
                data.Slice(4).Fill((byte)' ');
                byte[] text = Encoding.ASCII.GetBytes(message);
                text.CopyTo(data.Slice(4));
            }

            return CModeReply.Ok(EndCode.NormalCompletion, null, data, 1);
        },
        static (data, fields) =>
        {
            PlcStatus status = CModeResponse.ReadStatus(data);
            fields.Field("mode", status.Mode.ToString().ToUpperInvariant());
            fields.Field("statusWord", (long)status.StatusWord!.Value);
            fields.Field("userMemoryWritable", status.UserMemoryWritable == true);
            fields.Field("message", status.Message);
        });

    /// <summary>MM: PLC MODEL READ: end code and the model code (2).</summary>
    public static CModeCommandRow ModelRead { get; } = Simple(
        "MM",
        "PLC MODEL READ",
        CommandEffect.ReadOnly,
        CModeResponse.EndCodeLength + 2,
        static plc =>
        {
            Span<byte> data = stackalloc byte[2];
            HexAscii.WriteByte(plc.ModelCode, data);
            return CModeReply.Ok(EndCode.NormalCompletion, null, data, 2);
        },
        static (data, fields) =>
        {
            PlcModel model = CModeResponse.ReadModel(data);
            fields.Field("modelCode", model.Code.ToString("X2", System.Globalization.CultureInfo.InvariantCulture));
            fields.Field("model", model.Name);
        });

    /// <summary>KC: FORCED SET/RESET CANCEL (cancels every forced bit).</summary>
    public static CModeCommandRow ForcedCancel { get; } = Simple(
        "KC",
        "FORCED SET/RESET CANCEL",
        CommandEffect.NotRepeatable,
        CModeResponse.EndCodeLength,
        static plc =>
        {
            if (plc.Mode == PlcMode.Run)
            {
                return CModeReply.EndCodeOnly(EndCode.NotExecutableInRunMode);
            }

            plc.ReleaseAllForced();
            return CModeReply.EndCodeOnly(EndCode.NormalCompletion);
        },
        describeAnswer: null);

    /// <summary>XZ: ABORT. Stops the Host Link exchange in progress; the PLC sends no answer.</summary>
    public static CModeCommandRow Abort { get; } = Simple("XZ", "ABORT", CommandEffect.NotRepeatable, 0, static _ => null, describeAnswer: null, expectsAnswer: false);

    /// <summary>TS: TEST, the row of <see cref="TestCommand"/>; the link's presence probes and resynchronisation fences are TS.</summary>
    public static CModeCommandRow Test => TestCommand.CommandRow;

    /// <summary>WG: TC STATUS WRITE, which the older C-series list (C200HX, CQM1H); named only: CS/CJ have no WG.</summary>
    public static CModeCommandRow TcStatusWrite { get; } = NamedOnly("WG", "TC STATUS WRITE");

    /// <summary><c>**</c>: INITIALIZE (<c>@**</c>, no unit, no FCS, no answer).</summary>
    public static CModeCommandRow Initialize { get; } = NamedOnly("**", "INITIALIZE");

    /// <summary>IC: the answer to a header the PLC does not know (no end code).</summary>
    public static CModeCommandRow UndefinedCommand { get; } = new("IC", "UNDEFINED COMMAND (response)", CommandEffect.ReadOnly, 0) { IsCommand = false, AnswerHasEndCode = false };

    /// <summary>EX: TXD sent by the PLC in Host Link mode (no end code).</summary>
    public static CModeCommandRow Txd { get; } = new("EX", "TXD (PLC to host)", CommandEffect.ReadOnly, 122) { IsCommand = false, AnswerHasEndCode = false };

    /// <summary>FA: a FINS command or answer carried in a Host Link frame (executed by the FINS table's rows).</summary>
    public static CModeCommandRow Fins { get; } = NamedOnly("FA", "FINS COMMAND OVER HOST LINK");

    /// <summary>The MS command.</summary>
    public static CModeCommand StatusReadCommand { get; } = new SimpleCommand(StatusRead);

    /// <summary>The MM command.</summary>
    public static CModeCommand ModelReadCommand { get; } = new SimpleCommand(ModelRead);

    /// <summary>The KC command.</summary>
    public static CModeCommand ForcedCancelCommand { get; } = new SimpleCommand(ForcedCancel);

    /// <summary>The XZ command.</summary>
    public static CModeCommand AbortCommand { get; } = new SimpleCommand(Abort);

    /// <summary>Every row of the standard table.</summary>
    public static CModeCommandRow[] All()
    {
        var rows = new List<CModeCommandRow>();
        rows.AddRange(AreaReadCommand.Rows);
        rows.AddRange(AreaWriteCommand.Rows.Where(r => r is not null)!);
        rows.Add(NamedOnly("R#", "SV READ 1"));
        rows.Add(NamedOnly("R$", "SV READ 2"));
        rows.Add(NamedOnly("R%", "SV READ 3"));
        rows.Add(NamedOnly("W#", "SV CHANGE 1"));
        rows.Add(NamedOnly("W$", "SV CHANGE 2"));
        rows.Add(NamedOnly("W%", "SV CHANGE 3"));
        rows.Add(StatusRead);
        rows.Add(StatusChangeCommand.CommandRow);
        rows.Add(ErrorReadCommand.CommandRow);
        rows.Add(ForceBitCommand.SetRow);
        rows.Add(ForceBitCommand.ResetRow);
        rows.Add(MultipleForceCommand.CommandRow);
        rows.Add(ForcedCancel);
        rows.Add(ModelRead);
        rows.Add(TestCommand.CommandRow);
        rows.Add(NamedOnly("RP", "PROGRAM READ"));
        rows.Add(NamedOnly("WP", "PROGRAM WRITE"));
        rows.Add(NamedOnly("MI", "I/O TABLE GENERATE"));
        rows.Add(CompoundCommands.RegisterRow);
        rows.Add(CompoundCommands.ReadRow);
        rows.Add(Abort);
        rows.Add(Initialize);
        rows.Add(UndefinedCommand);
        rows.Add(Txd);
        rows.Add(Fins);
        return rows.ToArray();
    }

    private static CModeCommandRow NamedOnly(string header, string name) => new(header, name, CommandEffect.NotRepeatable, 0);

    private static CModeCommandRow Simple(string header, string name, CommandEffect effect, int maxAnswerText, Func<ICModePlc, CModeReply?> execute, CModeDescribeAnswer? describeAnswer, bool expectsAnswer = true)
    {
        CModeCommandRow row = null!;
        row = new CModeCommandRow(header, name, effect, maxAnswerText)
        {
            ExpectsAnswer = expectsAnswer,
            Parse = text =>
            {
                CModeCommandParser.ExpectLength(text, 0, header);
                return new SimpleCommand(row);
            },
            Execute = (_, plc, _) => execute(plc),
            DescribeAnswer = describeAnswer,
        };
        return row;
    }
}
