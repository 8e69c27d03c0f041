using System.Globalization;

namespace OmronHostLink.Com.Tests;

/// <summary>
/// VBScript through Wine's cscript, as a plant's scripts run on Windows: every method of OmronHostLink.Plc, the
/// Err.Number of each kind of failure, and the polling pattern without events. x64 through the 64-bit cscript; x86
/// through the 32-bit one against the x86 server, where Debian's wine32 installs.
/// </summary>
[Collection(WineCollection.Name)]
public sealed class VbScriptTests(WineBed bed)
{
    private static readonly TimeSpan ScriptTimeout = TimeSpan.FromMinutes(2);

    public static TheoryData<string> Architectures => new() { "x64", "x86" };

    [SkippableTheory]
    [MemberData(nameof(Architectures))]
    public async Task Every_method_reads_and_writes_the_simulator(string architecture)
    {
        SkipWithoutWine32(architecture);
        await using Simulation simulation = await Simulation.StartAsync();

        ProcessResult run = await Script(architecture, "methods.vbs", simulation.Endpoint);

        run.ExitCode.Should().Be(0, run.Output);
        run.Value("IsOpenBefore").Should().Be("False");
        run.Value("IsOpen").Should().Be("True");
        run.Value("Description").Should().Be(simulation.Endpoint);
        run.Value("Host").Should().Be("127.0.0.1");
        run.Value("TcpPort").Should().Be(simulation.Endpoint.Split(':')[1]);
        run.Value("PortName").Should().BeEmpty();
        run.Value("UnitNumber").Should().Be("0");
        run.Value("CommandSet").Should().Be("CMode");
        run.Value("BaudRate").Should().Be("9600");
        run.Value("Parity").Should().Be("E");
        run.Value("DataBits").Should().Be("7");
        run.Value("StopBits").Should().Be("2");
        run.Value("TurnaroundAllowance").Should().Be("2000");
        run.Value("ReadRetries").Should().Be("1");

        run.Value("ReadWords").Should().Be("1000 1001 1002 1003 1004 1005 1006 1007 1008 1009");
        run.Value("ReadWordsType").Should().Be("Long");
        run.Value("ReadWord").Should().Be("1005");
        run.Value("ReadBit").Should().Be("True");
        Number(run.Value("ReadReal")).Should().Be(1.5);
        run.Value("ReadRealType").Should().Be("Single");
        run.Value("ReadBcd").Should().Be("1234");
        Number(run.Value("ReadLReal")).Should().Be(-2.75);
        run.Value("ReadDint").Should().Be("-70000");
        run.Value("ReadString").Should().Be("ABCDEFGH");
        Number(run.Value("Read")).Should().Be(1.5);
        run.Value("ReadTags").Replace(',', '.').Should().Be("1000 1.5 1234 True");
        run.Value("ReadMode").Should().Be("PROGRAM");

        run.Value("SetMode").Should().Be("MONITOR");
        simulation.Unit0.Mode.Should().Be(PlcMode.Monitor);
        run.Value("WriteWord").Should().Be("4321");
        simulation.Unit0.ReadWords("D200", 1).Should().Equal(4321);
        run.Value("WriteWords").Should().Be("1 2 65535 65535");
        simulation.Unit0.ReadWords("D210", 4).Should().Equal(1, 2, 0xFFFF, 0xFFFF);
        Number(run.Value("WriteReal")).Should().Be(2.5);
        BitConverter.Int32BitsToSingle(simulation.Unit0.ReadWords("D140", 2) is var real ? real[0] | (real[1] << 16) : 0).Should().Be(2.5f);
        run.Value("WriteBcd").Should().Be("5678");
        simulation.Unit0.ReadWords("D152", 1).Should().Equal(0x5678);
        Number(run.Value("WriteLReal")).Should().Be(0.125);
        run.Value("WriteDint").Should().Be("-123456");
        run.Value("WriteString").Should().Be("HELLO");
        simulation.Unit0.ReadWords("D190", 3).Should().Equal(0x4845, 0x4C4C, 0x4F00);
        run.Value("Write").Should().Be("-5");
        simulation.Unit0.ReadWords("D194", 1).Should().Equal(0xFFFB);

        run.Value("ReadStatus").Should().StartWith("MONITOR ");
        run.Value("ReadErrors").Should().NotBeEmpty();
        run.Value("ReadModel").Should().Contain("CS/CJ");
        run.Value("Test").Should().Be("True");
        run.Value("Unit1").Should().Be("2024");
        run.Value("Unit0").Should().Be("1000");
        run.Value("IsOpenAfter").Should().Be("False");
        run.Value("WriteBit").Should().Be("True");
        simulation.Unit0.GetBit("W10.05").Should().BeTrue();
        run.Value("Properties").Should().Be($"{simulation.Endpoint} unit 1 2024");
        run.Value("Done").Should().Be("yes");
    }

    [SkippableTheory]
    [MemberData(nameof(Architectures))]
    public async Task Each_failure_has_its_Err_Number_and_the_library_message(string architecture)
    {
        SkipWithoutWine32(architecture);
        await using Simulation simulation = await Simulation.StartAsync();

        ProcessResult run = await Script(architecture, "errors.vbs", simulation.Endpoint);

        run.ExitCode.Should().Be(0, run.Output);
        Error(run, "NotOpen").Should().Be((Documented.NotOpen, "The link is not open; call Open first."));
        Error(run, "Open").Number.Should().Be(0);
        Error(run, "SetModeRun").Number.Should().Be(0);
        simulation.Unit0.Mode.Should().Be(PlcMode.Run);
        (int number, string description) = Error(run, "WriteInRunMode");
        number.Should().Be(Documented.EndCodeRunMode);
        description.Should().Contain("RUN mode");
        simulation.Unit0.ReadWords("D200", 1).Should().Equal(0);

        (number, description) = Error(run, "SilentUnit");
        number.Should().Be(Documented.Timeout);
        description.Should().Contain("unit 07");

        Error(run, "BadAddress").Number.Should().Be(Documented.InvalidArgument);
        Error(run, "BadCount").Number.Should().Be(Documented.InvalidArgument);
        Error(run, "BadValue").Should().Be((Documented.InvalidArgument, "A word is 0 to 65535 (or -32768 to -1 for the same bits); 70000 is neither."));
        Error(run, "BadMode").Should().Be((Documented.InvalidArgument, "'STOP' is not a mode; use PROGRAM, MONITOR or RUN."));
        Error(run, "BadUnit").Should().Be((Documented.InvalidArgument, "UnitNumber 32 is not a unit number; use 0-31."));
        Error(run, "OpenTwice").Number.Should().Be(Documented.NotOpen);
        (number, description) = Error(run, "BadParity");
        number.Should().Be(Documented.InvalidArgument);
        description.Should().StartWith("The connection string 'COM3:9600,X,7,2' cannot be used: Serial:Parity");
        Error(run, "BadPort").Description.Should().Contain("Tcp");
        Error(run, "OpenRefused").Number.Should().Be(0, "nothing opens until the first exchange");
        Error(run, "ConnectionRefused").Number.Should().Be(Documented.Connection);
        run.Value("Done").Should().Be("yes");
    }

    [SkippableTheory]
    [MemberData(nameof(Architectures))]
    public async Task A_script_without_events_polls_the_watch_for_changes(string architecture)
    {
        SkipWithoutWine32(architecture);
        await using Simulation simulation = await Simulation.StartAsync();
        await using WineProcess script = bed.Launch(bed.WineFor(architecture), ["cscript", "//nologo", WineBed.WindowsPath(ScriptPath("polling.vbs")), simulation.Endpoint]);

        await script.WaitForLineAsync(l => l == "Ready=yes", ScriptTimeout, "Ready=yes");
        script.Lines.Should().Contain("IsWatching=True").And.Contain("Initial=D100 1000");
        script.Lines.Select(l => l.Replace(',', '.')).Should().Contain("Initial=D130:float 1.5");
        simulation.Unit0.WriteWords("D100", [777]);

        (await script.WaitForExitAsync(ScriptTimeout)).Should().Be(0, script.Output);
        script.Lines.Should().Contain("Changed=D100 777").And.Contain("WatchError=[]").And.Contain("StoppedWatching=False");
        script.Lines.Should().NotContain("Timeout=yes");
    }

    private static (int Number, string Description) Error(ProcessResult run, string name)
    {
        string value = run.Value(name);
        int bar = value.IndexOf('|', StringComparison.Ordinal);
        return (int.Parse(value[..bar], CultureInfo.InvariantCulture), value[(bar + 1)..]);
    }

    private static double Number(string text) => double.Parse(text.Replace(',', '.'), CultureInfo.InvariantCulture);

    private void SkipWithoutWine32(string architecture)
        => Skip.If(architecture == "x86" && bed.Wine32 is null, "No 32-bit Wine for the x86 server: " + bed.X86Status);

    private Task<ProcessResult> Script(string architecture, string script, params string[] arguments)
        => bed.RunAsync(bed.WineFor(architecture), ["cscript", "//nologo", WineBed.WindowsPath(ScriptPath(script)), .. arguments], ScriptTimeout);

    internal static string ScriptPath(string script) => Path.Combine(AppContext.BaseDirectory, "Scripts", script);
}
