namespace OmronHostLink.Tests.Settings;

/// <summary>
/// The one duration grammar reads each text of <see cref="DurationTexts"/> or says how to write it; every reader of
/// durations gives the same time or the same refusal for the same texts (see <see cref="DurationTexts"/>).
/// </summary>
public sealed class DurationGrammarTests
{
    /// <summary>Each text, and the time it is (in ticks), or null where it is refused.</summary>
    public static IEnumerable<object?[]> Texts => DurationTexts.All;

    [Theory]
    [MemberData(nameof(Texts))]
    public void The_grammar_reads_the_text_or_says_how_to_write_it(string text, long? ticks)
    {
        bool read = Duration.TryParse(text, out TimeSpan value, out string? error);

        read.Should().Be(ticks is not null, error);
        if (ticks is { } t)
        {
            value.Should().Be(TimeSpan.FromTicks(t));
            error.Should().BeNull();
        }
        else
        {
            error.Should().StartWith($"'{text}' ").And.Contain("write");
            FluentActions.Invoking(() => Duration.Parse(text)).Should().Throw<FormatException>().WithMessage(error);
        }
    }
}
