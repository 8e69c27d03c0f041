using System.CommandLine;
using System.Globalization;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Cli.Commands;

/// <summary>
/// <c>demo</c>: the README's main job without hardware: against a simulator in this process, check that the PLC
/// answers, read its model, status and errors, and read 30 consecutive DM words, showing every frame exchanged.
/// </summary>
internal static class DemoCommand
{
    public const int Words = 30;

    public static Command Create(CliContext context)
    {
        var command = new Command("demo", "Run the main job against a simulated PLC in this process (no hardware): check that it answers, read status and errors, read 30 DM words; shows the frames exchanged.");
        context.SetAction(command, null, async (_, output, ct) =>
        {
            TextWriter w = output.Out;
            var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0], InitialMode = PlcMode.Run });
            for (int i = 0; i < Words; i++)
            {
                plc.WriteWord(PlcArea.Dm, 100 + i, (ushort)(1000 + (i * 37)));
            }

            plc.FalMessage = "DEMO LINE 1";

            (Stream hostEnd, Stream plcEnd) = InMemoryLink.CreatePair();
            using var stop = CancellationTokenSource.CreateLinkedTokenSource(ct);
            Task session = plc.RunAsync(plcEnd, stop.Token);
            try
            {
                await using HostLinkClient client = HostLinkClient.ForStream(hostEnd, new HostLinkClientOptions { UnitNumber = 0 });
                client.FrameObserver = (sent, frame) => w.WriteLine("    " + OutputWriter.FormatFrame(sent, frame.Span, DateTime.Now));
                w.WriteLine("hostlink demo: a simulated CS/CJ PLC, unit 00, in this process (no hardware needed).");
                w.WriteLine();

                w.WriteLine("1. Does the PLC answer? (TS loopback test)");
                TimeSpan rtt = await client.TestAsync("HELLO PLC", ct).ConfigureAwait(false);
                w.WriteLine($"   Yes: unit 00 echoed the text in {rtt.TotalMilliseconds.ToString("0.0", CultureInfo.InvariantCulture)} ms.");
                w.WriteLine();

                w.WriteLine("2. Which PLC is it? (MM model read)");
                PlcModel model = await client.ReadModelAsync(ct).ConfigureAwait(false);
                w.WriteLine($"   {model}");
                w.WriteLine();

                w.WriteLine("3. Operating mode and status (MS status read)");
                PlcStatus status = await client.ReadStatusAsync(ct).ConfigureAwait(false);
                Indent(w, x => StatusCommand.WriteHuman(x, 0, status));
                w.WriteLine();

                w.WriteLine("4. Errors (MF error read)");
                PlcErrorInfo errors = await client.ReadErrorsAsync(false, ct).ConfigureAwait(false);
                Indent(w, x => ErrorsCommand.WriteHuman(x, 0, errors, false));
                w.WriteLine();

                w.WriteLine($"5. Read {Words} consecutive DM words, D100-D{100 + Words - 1} (RD: one command, one snapshot)");
                ushort[] dm = await client.ReadWordsAsync("D100", Words, ct).ConfigureAwait(false);
                for (int i = 0; i < dm.Length; i++)
                {
                    w.WriteLine($"   D{100 + i,-4} {Numbers.Hex(dm[i])}  {dm[i],5}");
                }

                w.WriteLine();
                w.WriteLine("Done. The same against a real PLC: hostlink status --port /dev/ttyUSB0; hostlink read D100 30 --port /dev/ttyUSB0.");
                w.WriteLine("Or against a simulator on TCP: hostlink simulate --mode run, then hostlink read D100 30 --tcp 127.0.0.1:9600.");
            }
            finally
            {
                await stop.CancelAsync().ConfigureAwait(false);
                await plcEnd.DisposeAsync().ConfigureAwait(false);
                await session.ConfigureAwait(false);
            }

            return ExitCodes.Success;
        });
        return command;
    }

    private static void Indent(TextWriter w, Action<TextWriter> write)
    {
        var text = new StringWriter(CultureInfo.InvariantCulture);
        write(text);
        foreach (string line in text.ToString().Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries))
        {
            w.WriteLine("   " + line);
        }
    }
}
