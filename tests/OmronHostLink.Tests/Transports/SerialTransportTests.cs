using System.Diagnostics;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Transports;

/// <summary>The serial transport (System.IO.Ports) over real pseudo-terminal pairs made by socat.</summary>
[Trait("Category", "Slow")]
public sealed class SerialTransportTests
{
    // Upper bound for anything that should happen at once; a hang fails the test instead of the run.
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(10);
    private static readonly TimeSpan Prompt = TimeSpan.FromSeconds(1);

    private static Task<Stream> OpenPortAsync(string path) => SocatPtyPair.OpenAsync(path);

    private static async Task<byte[]> ReadExactlyAsync(Stream stream, int count)
    {
        var buffer = new byte[count];
        using var cts = new CancellationTokenSource(Patience);
        await stream.ReadExactlyAsync(buffer, cts.Token);
        return buffer;
    }

    /// <summary>
    /// The read is pending in the port's I/O loop: that loop (one per port, reads and writes alike) has since carried out
    /// a write queued after the read — one byte, read at the peer — and the read still waits.
    /// </summary>
    private static async Task AssertPendingAsync(Task task, Stream port, Stream peer)
    {
        await port.WriteAsync("."u8.ToArray());
        (await ReadExactlyAsync(peer, 1)).Should().Equal((byte)'.');
        task.IsCompleted.Should().BeFalse("nothing has been sent to it yet");
    }

    [Fact]
    public async Task Open_returns_a_readable_writable_non_seekable_stream()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using Stream a = await OpenPortAsync(pair.PathA);

        a.CanRead.Should().BeTrue();
        a.CanWrite.Should().BeTrue();
        a.CanSeek.Should().BeFalse();
        a.Invoking(s => s.Length).Should().Throw<NotSupportedException>();
        a.Invoking(s => s.Position).Should().Throw<NotSupportedException>();
        a.Invoking(s => s.Seek(0, SeekOrigin.Begin)).Should().Throw<NotSupportedException>();
    }

    [Fact]
    public async Task A_pty_opens_with_the_default_7E2_settings_again_and_again_in_its_own_8_bit_framing()
    {
        // Some kernels refuse a pty any change of data bits or parity after its first user closed it (EINVAL).
        await using var pair = await SocatPtyPair.StartAsync();
        var settings = new SerialLineSettings { PortName = pair.PathA };
        for (int i = 0; i < 3; i++)
        {
            var transport = new SerialTransport(settings);
            Stream stream = await transport.OpenAsync(CancellationToken.None);
            transport.IsPseudoTerminal.Should().BeTrue();
            transport.LineTiming!.BitsPerCharacter.Should().Be(11, "deadlines keep the configured 7E2 character time");
            await transport.CloseAsync();
            stream.CanRead.Should().BeFalse("closing the transport closed the port");
        }
    }

    [Fact]
    public async Task Bytes_written_on_A_arrive_on_B_intact_and_back()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);

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
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);
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
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);
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
    public async Task Synchronous_Read_Write_and_Flush_work()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);
        byte[] message = "@00TS HELLO*\r"u8.ToArray();

        a.Write(message, 0, message.Length);
        a.Flush();
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
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);

        using var cts = new CancellationTokenSource();
        Task<int> read = b.ReadAsync(new byte[16], cts.Token).AsTask();
        await AssertPendingAsync(read, b, a);

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
        using Stream a = await OpenPortAsync(pair.PathA);

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
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);
        await a.WriteAsync("X"u8.ToArray());

        await b.Invoking(s => s.ReadAsync(new byte[1], new CancellationToken(canceled: true)).AsTask())
            .Should().ThrowAsync<OperationCanceledException>();
        (await ReadExactlyAsync(b, 1)).Should().Equal((byte)'X');
    }

    [Fact]
    public async Task Dispose_during_a_pending_read_completes_it()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);
        Task<int> read = a.ReadAsync(new byte[16]).AsTask();
        await AssertPendingAsync(read, a, b);

        var clock = Stopwatch.StartNew();
        a.Dispose();
        Exception? error = await Record.ExceptionAsync(() => read.WaitAsync(Patience));
        clock.Elapsed.Should().BeLessThan(Prompt);
        error.Should().Match<Exception>(e => e is ObjectDisposedException || e is OperationCanceledException);
    }

    [Fact]
    public async Task Closing_the_transport_during_a_read_with_a_cancellable_token_completes_it()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        var transport = new SerialTransport(new SerialLineSettings { PortName = pair.PathA });
        Stream a = await transport.OpenAsync(CancellationToken.None);
        using Stream b = await OpenPortAsync(pair.PathB);
        using var cts = new CancellationTokenSource();
        Task<int> read = a.ReadAsync(new byte[16], cts.Token).AsTask();
        await AssertPendingAsync(read, a, b);

        var clock = Stopwatch.StartNew();
        await transport.CloseAsync();
        Exception? error = await Record.ExceptionAsync(() => read.WaitAsync(Patience));
        clock.Elapsed.Should().BeLessThan(Prompt);
        error.Should().BeOfType<ObjectDisposedException>();
    }

    [Fact]
    public async Task Operations_after_Dispose_throw_ObjectDisposedException()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        Stream a = await OpenPortAsync(pair.PathA);
        a.Dispose();
        a.Dispose(); // twice is harmless

        a.CanRead.Should().BeFalse();
        a.CanWrite.Should().BeFalse();
        await a.Invoking(s => s.ReadAsync(new byte[1]).AsTask()).Should().ThrowAsync<ObjectDisposedException>();
        await a.Invoking(s => s.WriteAsync(new byte[1]).AsTask()).Should().ThrowAsync<ObjectDisposedException>();
        a.Invoking(s => s.Flush()).Should().Throw<ObjectDisposedException>();
    }

    [Fact]
    public async Task Killing_socat_during_a_read_surfaces_IOException_saying_the_device_hung_up()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB);
        Task<int> read = a.ReadAsync(new byte[16]).AsTask();
        await AssertPendingAsync(read, a, b);

        await pair.CloseAsync();

        Exception? error = await Record.ExceptionAsync(() => read.WaitAsync(Patience));
        error.Should().BeOfType<IOException>().Which.Message.Should().Contain("hung up").And.Contain("pseudo-terminal");
    }

    [Fact]
    public async Task After_the_link_is_lost_every_read_and_write_throws_IOException_without_spinning()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        using Stream a = await OpenPortAsync(pair.PathA);
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
        using Stream a = await OpenPortAsync(pair.PathA);
        using Stream b = await OpenPortAsync(pair.PathB); // open but never read: the pty buffers and socat fill up

        using var cts = new CancellationTokenSource();
        Task write = a.WriteAsync(new byte[4 * 1024 * 1024], cts.Token).AsTask();
        write.IsCompleted.Should().BeFalse("4 MB cannot fit in the pty buffers");

        var clock = Stopwatch.StartNew();
        cts.Cancel();
        await write.Invoking(t => t.WaitAsync(Patience)).Should().ThrowAsync<OperationCanceledException>();
        clock.Elapsed.Should().BeLessThan(Prompt);
    }

    [Fact]
    public async Task The_transport_reopens_the_port_after_CloseAsync_and_a_lost_stream_is_replaced()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        await using var transport = new SerialTransport(new SerialLineSettings { PortName = pair.PathA });
        using Stream b = await OpenPortAsync(pair.PathB);

        Stream first = await transport.OpenAsync(CancellationToken.None);
        (await transport.OpenAsync(CancellationToken.None)).Should().BeSameAs(first, "an open port is handed out again");
        await transport.CloseAsync();

        Stream second = await transport.OpenAsync(CancellationToken.None);
        second.Should().NotBeSameAs(first);
        await second.WriteAsync("AGAIN"u8.ToArray());
        (await ReadExactlyAsync(b, 5)).Should().Equal("AGAIN"u8.ToArray());
    }

    [Fact]
    public void Invalid_settings_are_rejected_before_anything_is_opened()
    {
        FluentActions.Invoking(() => new SerialTransport(new SerialLineSettings { PortName = "/dev/null", DataBits = 5 }))
            .Should().Throw<ArgumentException>().WithMessage("*DataBits*");
        FluentActions.Invoking(() => new SerialTransport(null!)).Should().Throw<ArgumentNullException>();
    }

    [Fact]
    public void The_transport_keeps_its_own_copy_of_the_settings()
    {
        var settings = new SerialLineSettings { PortName = "/dev/ttyUSB0" };
        var transport = new SerialTransport(settings);
        settings.PortName = "/dev/ttyUSB1";
        settings.BaudRate = 115200;

        transport.Description.Should().Be("/dev/ttyUSB0 9600 7E2");
        transport.LineTiming!.BaudRate.Should().Be(9600);
    }
}
