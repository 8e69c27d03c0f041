using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Reliability;

/// <summary>
/// Every public client method that takes input refuses bad input before a single byte reaches the stream: the client
/// sits on a <see cref="RecordingStream"/> that fails the test if anything is written. Each row names the call, the
/// exception type it must raise and a fragment the message must contain (the problem in the user's words).
/// </summary>
public sealed class BadInputTests
{
    public sealed record Row(string Name, Func<HostLinkUnit, Task> Call, Type Exception, string MessageNames, HostLinkCommandSet Protocol = HostLinkCommandSet.CMode)
    {
        public override string ToString() => Name;
    }

    private static readonly Row[] Rows =
    {
        // Addresses.
        new("read: null address", u => u.ReadWordsAsync((string)null!, 1), typeof(ArgumentNullException), "text"),
        new("read: empty address", u => u.ReadWordsAsync(string.Empty, 1), typeof(FormatException), "address"),
        new("read: unknown area", u => u.ReadWordsAsync("X100", 1), typeof(FormatException), "X100"),
        new("read: D32768 beyond DM", u => u.ReadWordsAsync("D32768", 1), typeof(FormatException), "32768"),
        new("read: negative word", u => u.ReadWordsAsync("D-1", 1), typeof(FormatException), "D-1"),
        new("read: D10000 beyond C-mode", u => u.ReadWordsAsync("D10000", 1), typeof(ArgumentOutOfRangeException), "D10000"),
        new("read: W area in C-mode", u => u.ReadWordsAsync("W10", 1), typeof(ArgumentException), "W"),
        new("read: EM bank 13", u => u.ReadWordsAsync("E13_0", 1), typeof(FormatException), "13"),
        new("read: non-ASCII address", u => u.ReadWordsAsync("D１００", 1), typeof(FormatException), "D"),
        new("read: address with CR", u => u.ReadWordsAsync("D1\r", 1), typeof(FormatException), "control character"),
        new("read: address with *", u => u.ReadWordsAsync("D1*", 1), typeof(FormatException), "D1"),
        new("read: address with NUL", u => u.ReadWordsAsync("D1\0", 1), typeof(FormatException), "control character"),
        new("read: bit 16", u => u.ReadBitAsync("CIO10.16"), typeof(FormatException), "16"),

        // Counts.
        new("read: count 0", u => u.ReadWordsAsync("D0", 0), typeof(ArgumentOutOfRangeException), "count"),
        new("read: count -1", u => u.ReadWordsAsync("D0", -1), typeof(ArgumentOutOfRangeException), "count"),
        new("read: count past the area", u => u.ReadWordsAsync("D9999", 2), typeof(ArgumentOutOfRangeException), "9999"),
        new("read: count over any limit", u => u.ReadWordsAsync("D0", 100_000), typeof(ArgumentOutOfRangeException), "100000"),
        new("FINS read: count past DM", u => u.ReadWordsAsync("D32767", 2), typeof(ArgumentOutOfRangeException), "32767", HostLinkCommandSet.Fins),
        new("write: empty data", u => u.WriteWordsAsync("D0", ReadOnlyMemory<ushort>.Empty), typeof(ArgumentOutOfRangeException), "count"),
        new("write: past the area", u => u.WriteWordsAsync("D9999", new ushort[2]), typeof(ArgumentOutOfRangeException), "9999"),
        new("write: AR read-only part", u => u.WriteWordAsync("A0", 1), typeof(ArgumentException), "A"),
        new("read string: length 0", u => u.ReadStringAsync("D0", 0), typeof(ArgumentOutOfRangeException), "length"),
        new("fill: count 0", u => u.FillAsync("D0", 0, 1), typeof(ArgumentOutOfRangeException), "count", HostLinkCommandSet.Fins),
        new("transfer: past DM", u => u.TransferAsync("D0", "D32767", 2), typeof(ArgumentOutOfRangeException), "32767", HostLinkCommandSet.Fins),
        new("error log: count 0", u => u.ReadErrorLogAsync(0, 0), typeof(ArgumentOutOfRangeException), "count", HostLinkCommandSet.Fins),
        new("error log: count 54", u => u.ReadErrorLogAsync(0, 54), typeof(ArgumentOutOfRangeException), "count", HostLinkCommandSet.Fins),
        new("read multiple: null", u => u.ReadScatteredAsync(null!), typeof(ArgumentNullException), "addresses", HostLinkCommandSet.Fins),
        new("read multiple: empty", u => u.ReadScatteredAsync(Array.Empty<string>()), typeof(ArgumentException), "item", HostLinkCommandSet.Fins),
        new("read multiple: bad address", u => u.ReadScatteredAsync(new[] { "D0", "Q7" }), typeof(FormatException), "Q7", HostLinkCommandSet.Fins),

        // Values.
        new("BCD 10000", u => u.WriteBcdAsync("D0", 10000), typeof(ArgumentOutOfRangeException), "10000"),
        new("BCD -1", u => u.WriteBcdAsync("D0", -1), typeof(ArgumentOutOfRangeException), "-1"),
        new("string: non-ASCII", u => u.WriteStringAsync("D0", "naïve"), typeof(ArgumentException), "ASCII"),
        new("string: null", u => u.WriteStringAsync("D0", null!), typeof(ArgumentNullException), "text"),
        new("string: longer than the area", u => u.WriteStringAsync("D9990", new string('a', 40)), typeof(ArgumentOutOfRangeException), "9990"),
        new("TS: *", u => u.TestAsync("A*B"), typeof(ArgumentException), "*"),
        new("TS: @", u => u.TestAsync("A@B"), typeof(ArgumentException), "@"),
        new("TS: CR", u => u.TestAsync("A\rB"), typeof(ArgumentException), "text"),
        new("TS: non-ASCII", u => u.TestAsync("é"), typeof(ArgumentException), "text"),
        new("TS: 123 characters", u => u.TestAsync(new string('A', 123)), typeof(ArgumentException), "122"),
        new("TS: null", u => u.TestAsync(null!), typeof(ArgumentNullException), "text"),
        new("bit write: word address", u => u.WriteBitAsync("D10", true), typeof(ArgumentException), "D10"),
        new("bit read: word address", u => u.ReadBitAsync("D10"), typeof(ArgumentException), "D10"),
        new("force: word address", u => u.ForceBitAsync("CIO10", FinsForceAction.ForceSet), typeof(ArgumentException), "CIO", HostLinkCommandSet.Fins),
        new("mode: undefined", u => u.SetModeAsync((PlcMode)99), typeof(ArgumentOutOfRangeException), "mode"),
        new("FINS run: PROGRAM", u => u.RunAsync(PlcMode.Program), typeof(ArgumentException), "StopAsync", HostLinkCommandSet.Fins),
        new("clock: year 1960", u => u.WriteClockAsync(new DateTime(1960, 1, 1)), typeof(ArgumentOutOfRangeException), "1960", HostLinkCommandSet.Fins),

        // Units.
        new("unit -1", u => Task.FromResult(u.Unit(-1)), typeof(ArgumentOutOfRangeException), "-1"),
        new("unit 32", u => Task.FromResult(u.Unit(32)), typeof(ArgumentOutOfRangeException), "32"),
        new("unit 99", u => Task.FromResult(u.Unit(99, HostLinkCommandSet.Fins)), typeof(ArgumentOutOfRangeException), "99"),
    };

    public static IEnumerable<object[]> Cases => Rows.Select(r => new object[] { r });

    [Theory]
    [MemberData(nameof(Cases))]
    public async Task Bad_input_is_refused_before_anything_is_sent(Row row)
    {
        var stream = new RecordingStream();
        await using (HostLinkClient client = HostLinkClient.ForStream(stream, new HostLinkClientOptions { CommandSet = row.Protocol }))
        {
            Exception? caught = null;
            try
            {
                await row.Call(client);
            }
            catch (Exception e)
            {
                caught = e;
            }

            caught.Should().NotBeNull($"{row.Name} must be refused");
            caught!.GetType().Should().Be(row.Exception, $"{row.Name}: {caught}");
            caught.Message.Should().Contain(row.MessageNames, $"the message of {row.Name} names the problem");
        }

        stream.Written.Should().Be(0, $"{row.Name} must not reach the wire");
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(32)]
    [InlineData(99)]
    public void Client_options_with_a_bad_unit_are_refused_at_creation(int unit)
    {
        var stream = new RecordingStream();
        FluentActions.Invoking(() => HostLinkClient.ForStream(stream, new HostLinkClientOptions { UnitNumber = unit }))
            .Should().Throw<ArgumentOutOfRangeException>().WithMessage($"*{unit}*");
        stream.Written.Should().Be(0);
    }

    /// <summary>A stream that records what is written and never delivers anything to read.</summary>
    private sealed class RecordingStream() : PassThroughStream(Null)
    {
        private long _written;

        public long Written => Interlocked.Read(ref _written);

        public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        {
            // Nothing ever arrives: the read ends only when it is cancelled.
            await new TaskCompletionSource().Task.WaitAsync(cancellationToken);
            return 0;
        }

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            Interlocked.Add(ref _written, buffer.Length);
            return default;
        }
    }
}
