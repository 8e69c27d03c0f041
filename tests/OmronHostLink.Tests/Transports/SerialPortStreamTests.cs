using System.Diagnostics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Transports;

/// <summary>The Linux serial transport over real pseudo-terminal pairs made by socat.</summary>
[Trait("Category", "Slow")]
public sealed class SerialPortStreamTests
{
    // Upper bound for anything that should happen at once; a hang fails the test instead of the run.
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(10);
    private static readonly TimeSpan Prompt = TimeSpan.FromSeconds(1);

    private static Stream OpenPort(string path) => SerialPortStream.Open(new SerialLineSettings { PortName = path });

    private static async Task<byte[]> ReadExactlyAsync(Stream stream, int count)
    {
        var buffer = new byte[count];
        using var cts = new CancellationTokenSource(Patience);
        await stream.ReadExactlyAsync(buffer, cts.Token);
        return buffer;
    }

    private static async Task WaitUntilAsync(Func<bool> condition, string what)
    {
        var clock = Stopwatch.StartNew();
        while (!condition())
        {
            clock.Elapsed.Should().BeLessThan(Patience, $"waiting for {what}");
            await Task.Delay(10);
        }
    }

    private static async Task AssertPendingAsync(Task task)
    {
        // Give the read time to reach poll(); it must still be waiting.
        await Task.Delay(100);
        task.IsCompleted.Should().BeFalse("nothing has been sent yet");
    }

    [Fact]
    public async Task Open_returns_a_readable_writable_non_seekable_stream_that_can_discard_input()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);

        a.CanRead.Should().BeTrue();
        a.CanWrite.Should().BeTrue();
        a.CanSeek.Should().BeFalse();
        a.Should().BeAssignableTo<IInputDiscardable>();
        a.Invoking(s => s.Length).Should().Throw<NotSupportedException>();
        a.Invoking(s => s.Position).Should().Throw<NotSupportedException>();
        a.Invoking(s => s.Seek(0, SeekOrigin.Begin)).Should().Throw<NotSupportedException>();
    }

    [Fact]
    public async Task Bytes_written_on_A_arrive_on_B_intact_and_back()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB);

        byte[] command = "@00RD0000000151*\r"u8.ToArray();
        await a.WriteAsync(command);
        (await ReadExactlyAsync(b, command.Length)).Should().Equal(command);

        byte[] response = "@00RD00123457*\r"u8.ToArray();
        await b.WriteAsync(response);
        (await ReadExactlyAsync(a, response.Length)).Should().Equal(response);
    }

    [Fact]
    public async Task Two_kilobyte_blocks_with_every_byte_value_arrive_intact_in_both_directions()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB);
        byte[] block = Enumerable.Range(0, 2048).Select(i => (byte)(i * 7 + (i >> 8))).ToArray();
        block.Distinct().Should().HaveCount(256);

        foreach (var (from, to) in new[] { (a, b), (b, a) })
        {
            Task<byte[]> received = ReadExactlyAsync(to, block.Length);
            await from.WriteAsync(block);
            (await received).Should().Equal(block);
        }
    }

    [Fact]
    public async Task Byte_at_a_time_writes_and_reads_in_both_directions()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB);
        byte[] message = "@00MS5A*\r"u8.ToArray();

        foreach (var (from, to) in new[] { (a, b), (b, a) })
        {
            var received = new List<byte>();
            foreach (byte value in message)
            {
                await from.WriteAsync(new[] { value });
                byte[] one = new byte[1];
                using var cts = new CancellationTokenSource(Patience);
                (await to.ReadAsync(one, cts.Token)).Should().Be(1);
                received.Add(one[0]);
            }

            received.Should().Equal(message);
        }
    }

    [Fact]
    public async Task Synchronous_Read_and_Write_work()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB);
        byte[] message = "@00TS HELLO*\r"u8.ToArray();

        a.Write(message, 0, message.Length);
        var buffer = new byte[message.Length];
        int total = 0;
        while (total < buffer.Length)
        {
            int read = b.Read(buffer, total, buffer.Length - total);
            read.Should().BePositive();
            total += read;
        }

        buffer.Should().Equal(message);
    }

    [Fact]
    public async Task Cancelling_a_pending_ReadAsync_completes_promptly_and_the_stream_stays_usable()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB);

        using var cts = new CancellationTokenSource();
        Task<int> read = b.ReadAsync(new byte[16], cts.Token).AsTask();
        await AssertPendingAsync(read);

        var clock = Stopwatch.StartNew();
        cts.Cancel();
        await read.Invoking(t => t).Should().ThrowAsync<OperationCanceledException>();
        clock.Elapsed.Should().BeLessThan(Prompt);

        // Both directions still work afterwards, and nothing was lost.
        await a.WriteAsync("AFTER"u8.ToArray());
        (await ReadExactlyAsync(b, 5)).Should().Equal("AFTER"u8.ToArray());
        await b.WriteAsync("BACK"u8.ToArray());
        (await ReadExactlyAsync(a, 4)).Should().Equal("BACK"u8.ToArray());
    }

    [Fact]
    public async Task A_read_timed_out_by_CancelAfter_completes_promptly_and_repeatedly()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);

        for (int i = 0; i < 5; i++)
        {
            using var cts = new CancellationTokenSource(TimeSpan.FromMilliseconds(50));
            var clock = Stopwatch.StartNew();
            await a.Invoking(s => s.ReadAsync(new byte[1], cts.Token).AsTask()).Should().ThrowAsync<OperationCanceledException>();
            clock.Elapsed.Should().BeLessThan(Prompt);
        }
    }

    [Fact]
    public async Task An_already_cancelled_token_fails_ReadAsync_without_consuming_data()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB);
        await a.WriteAsync("X"u8.ToArray());

        await b.Invoking(s => s.ReadAsync(new byte[1], new CancellationToken(canceled: true)).AsTask())
            .Should().ThrowAsync<OperationCanceledException>();
        (await ReadExactlyAsync(b, 1)).Should().Equal((byte)'X');
    }

    [Fact]
    public async Task DiscardInput_drops_pending_bytes()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB);

        byte[] stale = "@00RD00STALE*\r"u8.ToArray();
        await a.WriteAsync(stale);
        await WaitUntilAsync(() => BytesToRead(b) == stale.Length, "the stale bytes to arrive");

        ((IInputDiscardable)b).DiscardInput();
        BytesToRead(b).Should().Be(0);

        await a.WriteAsync("FRESH"u8.ToArray());
        (await ReadExactlyAsync(b, 5)).Should().Equal("FRESH"u8.ToArray());
    }

    [Fact]
    public async Task Dispose_during_a_pending_read_completes_it()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        var a = OpenPort(pair.PathA);
        Task<int> read = a.ReadAsync(new byte[16]).AsTask();
        await AssertPendingAsync(read);

        var clock = Stopwatch.StartNew();
        a.Dispose();
        Exception? error = await Record.ExceptionAsync(() => read.WaitAsync(Patience));
        clock.Elapsed.Should().BeLessThan(Prompt);
        error.Should().Match<Exception>(e => e is ObjectDisposedException || e is OperationCanceledException);
    }

    [Fact]
    public async Task Dispose_during_a_read_with_a_cancellable_token_completes_it()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        var a = OpenPort(pair.PathA);
        using var cts = new CancellationTokenSource();
        Task<int> read = a.ReadAsync(new byte[16], cts.Token).AsTask();
        await AssertPendingAsync(read);

        a.Dispose();
        Exception? error = await Record.ExceptionAsync(() => read.WaitAsync(Patience));
        error.Should().BeOfType<ObjectDisposedException>();
    }

    [Fact]
    public async Task Operations_after_Dispose_throw_ObjectDisposedException()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        var a = OpenPort(pair.PathA);
        a.Dispose();
        a.Dispose(); // twice is harmless

        a.CanRead.Should().BeFalse();
        a.CanWrite.Should().BeFalse();
        await a.Invoking(s => s.ReadAsync(new byte[1]).AsTask()).Should().ThrowAsync<ObjectDisposedException>();
        await a.Invoking(s => s.WriteAsync(new byte[1]).AsTask()).Should().ThrowAsync<ObjectDisposedException>();
        a.Invoking(s => ((IInputDiscardable)s).DiscardInput()).Should().Throw<ObjectDisposedException>();
    }

    [Fact]
    public async Task Killing_socat_during_a_read_surfaces_IOException()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        Task<int> read = a.ReadAsync(new byte[16]).AsTask();
        await AssertPendingAsync(read);

        await pair.CloseAsync();

        Exception? error = await Record.ExceptionAsync(() => read.WaitAsync(Patience));
        error.Should().BeOfType<IOException>().Which.Message.Should().Contain(pair.PathA).And.Contain("closed or lost");
    }

    [Fact]
    public async Task After_the_link_is_lost_every_read_and_write_throws_IOException_without_spinning()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        await pair.CloseAsync();

        var clock = Stopwatch.StartNew();
        for (int i = 0; i < 3; i++)
        {
            await a.Invoking(s => s.ReadAsync(new byte[16]).AsTask().WaitAsync(Patience)).Should().ThrowAsync<IOException>();
            await a.Invoking(s => s.WriteAsync(new byte[16]).AsTask().WaitAsync(Patience)).Should().ThrowAsync<IOException>();
        }

        clock.Elapsed.Should().BeLessThan(Prompt);
    }

    [Fact]
    public async Task A_WriteAsync_blocked_because_nobody_reads_honours_cancellation()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using var a = OpenPort(pair.PathA);
        using var b = OpenPort(pair.PathB); // open but never read: the pty buffers and socat fill up

        using var cts = new CancellationTokenSource();
        Task write = a.WriteAsync(new byte[4 * 1024 * 1024], cts.Token).AsTask();
        await Task.Delay(200);
        write.IsCompleted.Should().BeFalse("4 MB cannot fit in the pty buffers");

        var clock = Stopwatch.StartNew();
        cts.Cancel();
        await write.Invoking(t => t.WaitAsync(Patience)).Should().ThrowAsync<OperationCanceledException>();
        clock.Elapsed.Should().BeLessThan(Prompt);
    }

    [Fact]
    public void Opening_a_missing_path_throws_SerialPortUnavailableException_naming_it()
    {
        const string path = "/tmp/does-not-exist-xyz";
        var error = FluentActions.Invoking(() => OpenPort(path)).Should().Throw<SerialPortUnavailableException>().Which;

        error.Message.Should().Contain(path).And.Contain("ENOENT");
        error.PortName.Should().Be(path);
        error.NativeErrorCode.Should().Be(2);
        error.Should().BeAssignableTo<IOException>();
    }

    [Fact]
    public void Opening_a_regular_file_throws_SerialPortUnavailableException_not_a_serial_device()
    {
        string path = Path.GetTempFileName();
        try
        {
            FluentActions.Invoking(() => OpenPort(path)).Should().Throw<SerialPortUnavailableException>()
                .Which.Message.Should().Contain(path).And.Contain("ENOTTY");
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public async Task Asking_for_DTR_on_a_pty_fails_with_a_clear_message()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        var settings = new SerialLineSettings { PortName = pair.PathA, DtrEnable = true };

        FluentActions.Invoking(() => SerialPortStream.Open(settings)).Should().Throw<SerialPortUnavailableException>()
            .Which.Message.Should().Contain(pair.PathA).And.Contain("DTR");
    }

    [Fact]
    public void Invalid_settings_are_rejected_before_anything_is_opened()
    {
        FluentActions.Invoking(() => SerialPortStream.Open(new SerialLineSettings { PortName = "/dev/null", DataBits = 5 }))
            .Should().Throw<ArgumentException>().WithMessage("*DataBits*");
        FluentActions.Invoking(() => SerialPortStream.Open(null!)).Should().Throw<ArgumentNullException>();
    }

    [Fact]
    public void GetPortNames_lists_only_existing_serial_devices_and_never_ptys()
    {
        IReadOnlyList<string> names = SerialPortStream.GetPortNames();

        names.Should().OnlyContain(n => File.Exists(n));
        names.Should().NotContain(n => n.StartsWith("/dev/pts/", StringComparison.Ordinal));
        names.Should().BeInAscendingOrder(StringComparer.Ordinal);
    }

    [Fact]
    public void The_termios_struct_matches_the_glibc_layout()
    {
        // sizeof/offsetof from <termios.h> on x86_64 and arm64 Linux.
        Unsafe.SizeOf<LinuxNative.Termios>().Should().Be(60);
        Marshal.OffsetOf<LinuxNative.Termios>(nameof(LinuxNative.Termios.c_line)).ToInt32().Should().Be(16);
        Marshal.OffsetOf<LinuxNative.Termios>(nameof(LinuxNative.Termios.c_ispeed)).ToInt32().Should().Be(52);
        Marshal.OffsetOf<LinuxNative.Termios>(nameof(LinuxNative.Termios.c_ospeed)).ToInt32().Should().Be(56);
        Unsafe.SizeOf<LinuxNative.PollFd>().Should().Be(8);
    }

    private static int BytesToRead(Stream stream) => ((LinuxSerialStream)stream).BytesToRead;
}
