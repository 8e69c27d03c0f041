using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;

namespace OmronHostLink.Simulator.Tests;

/// <summary>The test-facing memory API and initial memory from JSON.</summary>
public class VirtualPlcTests
{
    [Fact]
    public void Areas_have_CS_CJ_sizes()
    {
        var plc = new VirtualPlc();
        plc.WriteWords(PlcArea.Cio, 6143, [1]);
        plc.WriteWords(PlcArea.Work, 511, [1]);
        plc.WriteWords(PlcArea.Holding, 511, [1]);
        plc.WriteWords(PlcArea.Auxiliary, 959, [1]);
        plc.WriteWords(PlcArea.Dm, 32767, [1]);
        plc.WriteWords(PlcArea.Timer, 4095, [1]);
        plc.WriteWords(PlcArea.Counter, 4095, [1]);
        plc.WriteWords(PlcArea.Em, 32767, [1], bank: 12);
        FluentActions.Invoking(() => plc.WriteWords(PlcArea.Cio, 6144, [1])).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => plc.ReadWords(PlcArea.Dm, 32767, 2)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => plc.ReadWords(PlcArea.Em, 0, 1, bank: 13)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => plc.ReadWords(PlcArea.Dm, 0, 1, bank: 1)).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void Address_strings_bits_and_flags_work()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [1, 2, 3]);
        plc.ReadWords(PlcArea.Dm, 100, 3).Should().Equal(1, 2, 3);
        plc.SetBit("CIO10.03", true);
        plc.ReadWord(PlcArea.Cio, 10).Should().Be(8);
        plc.GetBit("10.03").Should().BeTrue();
        plc.SetBit("T7", true);
        plc.GetFlag(PlcArea.Timer, 7).Should().BeTrue();
        plc.GetBit("C7").Should().BeFalse();
        FluentActions.Invoking(() => plc.GetBit("D100")).Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Defaults_are_unit_0_PROGRAM_and_model_30()
    {
        var plc = new VirtualPlc();
        plc.Options.Units.Should().Equal(0);
        plc.Mode.Should().Be(PlcMode.Program);
        plc.ModelCode.Should().Be(0x30);
        plc.FalMessage.Should().BeNull();
    }

    [Fact]
    public void Invalid_options_are_refused()
    {
        FluentActions.Invoking(() => new VirtualPlc(new VirtualPlcOptions { Units = [32] })).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => new VirtualPlc(new VirtualPlcOptions { Units = [] })).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => new VirtualPlc(new VirtualPlcOptions { Faults = new FaultOptions { Drop = 1.5 } })).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => new VirtualPlc { FalMessage = new string('x', 17) }).Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Initial_memory_comes_from_a_JSON_file()
    {
        string path = Path.Combine(Path.GetTempPath(), $"sim-{Guid.NewGuid():N}.json");
        File.WriteAllText(path, """
            {
              // comments are allowed
              "D100": [1, 2, "0xFFFF"],
              "CIO0": [255],
              "H5": 7,
              "E2_100": [-1],
              "T3": "100",
              "CIO20.15": true,
              "flags": { "T3": true, "C4": 1 },
              "mode": "run",
              "model": "12",
              "falMessage": "PUMP FAULT",
              "errors": [32768, 1]
            }
            """);
        try
        {
            var plc = new VirtualPlc(new VirtualPlcOptions { InitialMemoryFile = path });
            plc.ReadWords("D100", 3).Should().Equal(1, 2, 0xFFFF);
            plc.ReadWord(PlcArea.Cio, 0).Should().Be(255);
            plc.ReadWord(PlcArea.Holding, 5).Should().Be(7);
            plc.ReadWord(PlcArea.Em, 100, bank: 2).Should().Be(0xFFFF);
            plc.ReadWord(PlcArea.Timer, 3).Should().Be(100);
            plc.ReadWord(PlcArea.Cio, 20).Should().Be(0x8000);
            plc.GetFlag(PlcArea.Timer, 3).Should().BeTrue();
            plc.GetFlag(PlcArea.Counter, 4).Should().BeTrue();
            plc.Mode.Should().Be(PlcMode.Run);
            plc.ModelCode.Should().Be(0x12);
            plc.FalMessage.Should().Be("PUMP FAULT");
            plc.Errors.FirstWord.Should().Be(0x8000);
            plc.Errors.SecondWord.Should().Be(1);
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Theory]
    [InlineData("[1]")]
    [InlineData("{\"D100\": [70000]}")]
    [InlineData("{\"Q5\": [1]}")]
    [InlineData("{\"mode\": \"debug\"}")]
    [InlineData("{\"D100\": {}}")]
    [InlineData("{\"D32767\": [1, 2]}")]
    [InlineData("not json")]
    public void Bad_initial_memory_is_reported_with_its_key(string json)
    {
        FluentActions.Invoking(() => new VirtualPlc().LoadJson(json)).Should().Throw<FormatException>();
    }
}
