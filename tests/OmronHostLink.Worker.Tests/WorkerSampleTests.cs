using System.Diagnostics;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Worker.Tests;

/// <summary>The worker sample, run as a process with its own appsettings.json, polls the simulator and logs what it reads.</summary>
public sealed class WorkerSampleTests
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(30);

    [Fact]
    public async Task The_sample_logs_the_typed_values_of_its_tags_and_each_change()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [120, 0xFEAC]);
        plc.WriteWords("D200", [0x0000, 0x41AC]); // 21.5, low word first
        await using var simulator = new TcpSimulatorHost(plc);
        await simulator.StartAsync();

        await using var sample = SampleProcess.Start(
            $"--HostLink:Clients:line1:Tcp=127.0.0.1:{simulator.EndPoint.Port}",
            $"--HostLink:Clients:line1:TurnaroundAllowance={Allowances.LosslessLineText}",
            "--Watch:line1:Interval=00:00:00.200");
        await sample.WaitForAsync("line1 D100:int16 = 120", Patience);
        await sample.WaitForAsync("line1 D101:int16 = -340", Patience);
        await sample.WaitForAsync("line1 D200:float = 21.5", Patience);

        plc.WriteWords("D101", [7]);
        await sample.WaitForAsync("line1 D101:int16 = 7 (was -340)", Patience);
    }

    [Fact]
    public async Task A_watch_naming_no_client_or_a_bad_tag_exits_2_naming_both()
    {
        await using var sample = SampleProcess.Start("--Watch:line2:Tags:0=D100", "--Watch:line1:Tags:1=D1x");

        int? exit = await sample.WaitForExitAsync(Patience);

        exit.Should().Be(2, sample.Output);
        sample.Output.Should().Contain("Watch:line2 names no client").And.Contain("Watch:line1:Tags:1: 'D1x' is not a tag")
            .And.NotContain("   at ", "a configuration mistake prints no stack trace");
    }

    /// <summary>The sample's own executable in this test's output folder, with its appsettings.json there.</summary>
    private sealed class SampleProcess : ProgramProcess
    {
        private SampleProcess(ProcessStartInfo start)
            : base(start)
        {
        }

        public static SampleProcess Start(params string[] args)
        {
            ProcessStartInfo start = DotnetStart(
                Path.Combine(AppContext.BaseDirectory, "OmronHostLink.Worker.dll"),
                ["--contentRoot", AppContext.BaseDirectory, .. args]);
            start.WorkingDirectory = AppContext.BaseDirectory;

            // Plain console lines, one entry a line, so the test reads the message text.
            start.Environment["Logging__Console__FormatterName"] = "simple";
            start.Environment["Logging__Console__FormatterOptions__SingleLine"] = "true";
            var sample = new SampleProcess(start);
            sample.Launch();
            return sample;
        }

        public async Task WaitForAsync(string text, TimeSpan timeout)
        {
            if (!await WaitForOutputAsync(text, timeout))
            {
                throw new Xunit.Sdk.XunitException($"The sample did not log '{text}' within {timeout.TotalSeconds} s. It logged:\n{Output}");
            }
        }
    }
}
