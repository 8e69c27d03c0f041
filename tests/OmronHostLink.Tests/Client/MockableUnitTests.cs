using NSubstitute;
using OmronHostLink.Planning;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// Application code written against <see cref="IHostLinkUnit"/> is tested with a test double instead of a wire, and
/// the same code runs unchanged against a real client.
/// </summary>
public sealed class MockableUnitTests
{
    public enum Alarm
    {
        Normal,
        High,
        Unknown,
    }

    [Fact]
    public async Task A_high_level_sets_the_alarm_bit_once()
    {
        IHostLinkUnit plc = Substitute.For<IHostLinkUnit>();
        plc.ReadAsync<float>("D100", Arg.Any<CancellationToken>()).Returns(95.5f);
        plc.ReadAsync<bool>("W0.00", Arg.Any<CancellationToken>()).Returns(false);

        (await new TankAlarm(plc).CheckAsync()).Should().Be(Alarm.High);

        await plc.Received(1).WriteAsync("W0.00", true, Arg.Any<CancellationToken>());
    }

    [Fact]
    public async Task An_alarm_already_in_the_right_state_is_not_written_again()
    {
        IHostLinkUnit plc = Substitute.For<IHostLinkUnit>();
        plc.ReadAsync<float>("D100", Arg.Any<CancellationToken>()).Returns(40f);
        plc.ReadAsync<bool>("W0.00", Arg.Any<CancellationToken>()).Returns(false);

        (await new TankAlarm(plc).CheckAsync()).Should().Be(Alarm.Normal);

        await plc.DidNotReceiveWithAnyArgs().WriteAsync<bool>(default!, default(bool), default);
    }

    [Fact]
    public async Task A_transient_link_failure_leaves_the_alarm_alone_and_a_refusal_is_not_hidden()
    {
        IHostLinkUnit plc = Substitute.For<IHostLinkUnit>();
        plc.ReadAsync<float>("D100", Arg.Any<CancellationToken>()).Returns(Task.FromException<float>(new HostLinkTimeoutException("No answer from unit 00.", TimeSpan.FromMilliseconds(300))));

        (await new TankAlarm(plc).CheckAsync()).Should().Be(Alarm.Unknown);
        await plc.DidNotReceiveWithAnyArgs().WriteAsync<bool>(default!, default(bool), default);

        plc.ReadAsync<float>("D100", Arg.Any<CancellationToken>()).Returns(Task.FromException<float>(new InvalidOperationException("not a link failure")));
        await FluentActions.Awaiting(() => new TankAlarm(plc).CheckAsync()).Should().ThrowAsync<InvalidOperationException>();
    }

    [Fact]
    public async Task A_consumer_of_WatchAsync_counts_outages_from_events_a_double_produces()
    {
        IHostLinkUnit plc = Substitute.For<IHostLinkUnit>();
        PlcTag level = PlcTag.Parse("D100:float");
        DateTimeOffset t0 = new(2026, 1, 1, 0, 0, 0, TimeSpan.Zero);
        plc.WatchAsync(Arg.Any<IReadOnlyList<PlcTag>>(), Arg.Any<TimeSpan>(), Arg.Any<CancellationToken>()).Returns(Events(
            WatchEvent.Changed(0, level, null, PlcValue.FromSingle(10f), t0),
            WatchEvent.Outage(new HostLinkConnectionException("Cannot connect."), t0.AddSeconds(1)),
            WatchEvent.Resumed(TimeSpan.FromSeconds(4), t0.AddSeconds(5)),
            WatchEvent.Changed(0, level, PlcValue.FromSingle(10f), PlcValue.FromSingle(12.5f), t0.AddSeconds(5))));

        LevelLog log = await LevelLog.FollowAsync(plc, level);

        log.Levels.Should().Equal(10f, 12.5f);
        log.Outages.Should().Be(1);
        log.Downtime.Should().Be(TimeSpan.FromSeconds(4));
        plc.Received(1).WatchAsync(Arg.Is<IReadOnlyList<PlcTag>>(t => t.Count == 1 && t[0] == level), Arg.Is(TimeSpan.FromSeconds(1)), Arg.Any<CancellationToken>());
    }

    [Fact]
    public async Task The_same_consumer_runs_against_a_real_client_through_the_interface()
    {
        await using InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { CommandSet = HostLinkCommandSet.Fins });
        IHostLinkClient client = line.Client;
        await client.WriteAsync("D100", 91f);

        (await new TankAlarm(client).CheckAsync()).Should().Be(Alarm.High);

        line.Plc.GetBit(PlcArea.Work, 0, 0).Should().BeTrue();
        client.Unit(0).Should().BeAssignableTo<IHostLinkUnit>().Which.UnitNumber.Should().Be(0);
        client.WithWordOrder(WordOrder.HighWordFirst).WordOrder.Should().Be(WordOrder.HighWordFirst);
    }

    private static async IAsyncEnumerable<WatchEvent> Events(params WatchEvent[] events)
    {
        foreach (WatchEvent e in events)
        {
            await Task.Yield();
            yield return e;
        }
    }

    /// <summary>Application code: raises W0.00 when the tank level in D100 is over 90.</summary>
    private sealed class TankAlarm(IHostLinkUnit plc)
    {
        public async Task<Alarm> CheckAsync(CancellationToken cancellationToken = default)
        {
            float level;
            try
            {
                level = await plc.ReadAsync<float>("D100", cancellationToken);
            }
            catch (HostLinkException e) when (e.IsTransient)
            {
                return Alarm.Unknown;
            }

            bool high = level > 90f;
            if (await plc.ReadAsync<bool>("W0.00", cancellationToken) != high)
            {
                await plc.WriteAsync("W0.00", high, cancellationToken);
            }

            return high ? Alarm.High : Alarm.Normal;
        }
    }

    /// <summary>Application code: follows a level tag and keeps its values and the link's downtime.</summary>
    private sealed class LevelLog
    {
        public List<float> Levels { get; } = new();

        public int Outages { get; private set; }

        public TimeSpan Downtime { get; private set; }

        public static async Task<LevelLog> FollowAsync(IHostLinkUnit plc, PlcTag level, CancellationToken cancellationToken = default)
        {
            var log = new LevelLog();
            await foreach (WatchEvent e in plc.WatchAsync(new[] { level }, TimeSpan.FromSeconds(1), cancellationToken))
            {
                switch (e.Kind)
                {
                    case WatchEventKind.Changed:
                        log.Levels.Add(e.NewValue.ToSingle());
                        break;
                    case WatchEventKind.Outage:
                        log.Outages++;
                        break;
                    case WatchEventKind.Resumed:
                        log.Downtime += e.Duration;
                        break;
                }
            }

            return log;
        }
    }
}
