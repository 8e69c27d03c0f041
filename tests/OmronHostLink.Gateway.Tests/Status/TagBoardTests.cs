using Microsoft.Extensions.Options;
using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Status;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// The Tags view's store: every configured tag listed from the start, an outcome taken by version so a page is sent
/// only what changed, the last value kept through a failure, and one history point a refresh interval at most; the
/// rates of the Lines view from samples of a running count.
/// </summary>
public sealed class TagBoardTests
{
    private static readonly DateTimeOffset T0 = new(2026, 11, 27, 8, 0, 0, TimeSpan.Zero);

    [Fact]
    public void Every_tag_is_listed_and_a_page_is_sent_only_what_changed()
    {
        TagBoard board = Board();
        board.All().Select(t => $"{t.Link}/{t.Unit}/{t.Name} {t.Address} {t.Type} {t.Count}").Should().Equal(
            "plc/0/levels D100 int16 4",
            "plc/0/speed D10 uint16 1",
            "plc/3/recipe D300 string 8");
        board.All().Should().OnlyContain(t => t.Quality == null && t.Value == null);
        board.Version.Should().Be(0);

        board.TagChanged(new TagChange("plc", 0, "speed", "D10", PlcValueType.UInt16, (ushort)1500, TagQuality.Good, T0));
        long version = board.Version;
        board.TagChanged(new TagChange("plc", 3, "recipe", "D300", PlcValueType.String, "MIX-A7", TagQuality.Good, T0));
        board.TagChanged(new TagChange("other", 0, "speed", "D10", PlcValueType.UInt16, (ushort)1, TagQuality.Good, T0)); // no such tag

        List<TagRow> changed = board.ChangedSince(version);
        changed.Should().ContainSingle().Which.Should().BeEquivalentTo(new { Index = 2, Value = "MIX-A7", Quality = "good", ReadTime = T0, Link = (string?)null, History = (double[]?)null });
        board.ChangedSince(board.Version).Should().BeEmpty();
        board.ChangedSince(0).Select(t => t.Index).Should().Equal([1, 2]);
    }

    [Fact]
    public void A_failure_keeps_the_last_value_read_and_says_why()
    {
        TagBoard board = Board();
        board.TagChanged(new TagChange("plc", 0, "speed", "D10", PlcValueType.UInt16, (ushort)1500, TagQuality.Good, T0));
        board.TagChanged(new TagChange("plc", 0, "speed", "D10", PlcValueType.UInt16, null, TagQuality.CommError, T0.AddSeconds(3), "No answer from unit 00 to RD"));

        TagRow speed = board.All()[1];
        speed.Value.Should().Be((ushort)1500);
        speed.Quality.Should().Be("comm-error");
        speed.ReadTime.Should().Be(T0);
        speed.Time.Should().Be(T0.AddSeconds(3));
        speed.Error.Should().Be("No answer from unit 00 to RD");
    }

    [Fact]
    public void The_history_keeps_one_value_a_refresh_interval_the_latest_standing_for_it()
    {
        TagBoard board = Board(refresh: TimeSpan.FromMilliseconds(500));
        for (int i = 0; i < 10; i++)
        {
            // Read every 100 ms: 1 s of reads is two points.
            board.TagChanged(new TagChange("plc", 0, "speed", "D10", PlcValueType.UInt16, (ushort)i, TagQuality.Good, T0.AddMilliseconds(100 * i)));
        }

        board.All()[1].History.Should().Equal([4.0, 9.0]);
        for (int i = 0; i < TagBoard.HistoryLength + 5; i++)
        {
            board.TagChanged(new TagChange("plc", 0, "speed", "D10", PlcValueType.UInt16, (ushort)(100 + i), TagQuality.Good, T0.AddSeconds(10 + i)));
        }

        double[] history = board.All()[1].History!;
        history.Should().HaveCount(TagBoard.HistoryLength);
        history[^1].Should().Be(100 + TagBoard.HistoryLength + 4);
        board.TagChanged(new TagChange("plc", 3, "recipe", "D300", PlcValueType.String, "MIX", TagQuality.Good, T0));
        board.All()[2].History.Should().BeEmpty("text has no sparkline");
    }

    [Theory]
    [InlineData((ushort)7, 7.0)]
    [InlineData((short)-7, -7.0)]
    [InlineData(2.5f, 2.5)]
    [InlineData(true, 1.0)]
    [InlineData(float.NaN, null)]
    [InlineData("text", null)]
    public void A_sparkline_draws_single_numbers_and_flags(object value, double? expected)
        => TagBoard.Numeric(value).Should().Be(expected);

    [Fact]
    public void A_rate_is_taken_over_the_last_seconds_of_samples()
    {
        var time = new FakeTimeProvider(T0);
        var rates = new TransactionRates(time);
        rates.Sample("plc", 100).Should().BeNull("one sample is no rate");
        time.Advance(TimeSpan.FromSeconds(1));
        rates.Sample("plc", 150).Should().Be(50);
        for (int i = 2; i <= 20; i++)
        {
            time.Advance(TimeSpan.FromSeconds(1));
            rates.Sample("plc", 100 + (i * 50) + (i > 10 ? (i - 10) * 50 : 0));
        }

        // From 11 s on, 100 a second: the window holds only that.
        rates.Sample("plc", 100 + (20 * 50) + (10 * 50)).Should().BeApproximately(100, 20);
        rates.Sample("other", 5).Should().BeNull();
    }

    private static TagBoard Board(TimeSpan? refresh = null)
    {
        var gateway = new GatewayOptions();
        var link = new LinkOptions();
        link.Groups["speed"] = new PollGroupOptions { Address = "D10", Type = "uint16" };
        link.Groups["levels"] = new PollGroupOptions { Address = "D100", Type = "int16", Count = 4 };
        link.Groups["recipe"] = new PollGroupOptions { Unit = 3, Address = "D300", Type = "string", Count = 8 };
        gateway.Links["plc"] = link;
        gateway.Links["off"] = new LinkOptions { Enabled = false, Groups = { ["x"] = new PollGroupOptions { Address = "D0" } } };
        return new TagBoard(Options.Create(gateway), Options.Create(new StatusOptions { RefreshInterval = refresh ?? TimeSpan.FromMilliseconds(500) }));
    }
}
