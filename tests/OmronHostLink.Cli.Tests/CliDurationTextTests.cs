using System.CommandLine;

namespace OmronHostLink.Cli.Tests;

/// <summary>A time option reads each text of <see cref="DurationTexts"/> as the core's grammar does: the same time, or the same refusal.</summary>
public sealed class CliDurationTextTests
{
    [Theory]
    [MemberData(nameof(DurationTexts.All), MemberType = typeof(DurationTexts))]
    public void The_console_reads_it_the_same(string text, long? ticks)
    {
        Option<TimeSpan?> interval = Durations.Option("--interval", "Between polls.", null, TimeSpan.Zero, TimeSpan.FromDays(1));
        var command = new RootCommand { interval };

        ParseResult parse = command.Parse(["--interval", text]);

        if (ticks is { } t)
        {
            parse.Errors.Should().BeEmpty();
            parse.GetValue(interval).Should().Be(TimeSpan.FromTicks(t));
        }
        else
        {
            parse.Errors.Select(e => e.Message).Should().Equal($"--interval: {DurationTexts.Refusal(text)}.");
        }
    }
}
