using System.Diagnostics.Metrics;
using System.Text;
using System.Text.Json;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Queue;
using OmronHostLink.Gateway.Writes;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// A write the gateway cannot carry out is refused or failed in the user's words, naming its tag: never with the text
/// of an exception from inside the gateway, and never for another tag.
/// </summary>
public sealed class WriteFailureTests : IDisposable
{
    private readonly ServiceProvider _services = new ServiceCollection().AddMetrics().BuildServiceProvider();

    public void Dispose() => _services.Dispose();

    [Theory]
    [InlineData("T5", "bit", 1, "[true]", "plc/0/tag: T5 is a timer/counter completion flag, which the PLC sets itself; it cannot be written.")]
    [InlineData("CIO10.00", "bit", 4, "[true,false,true,true]", "plc/0/tag: a writable bit group must have Count 1 (one bit, written on its own); it has 4.")]
    public async Task A_tag_that_cannot_be_written_is_refused_before_the_wire_whatever_its_configuration_said(string address, string type, int count, string json, string expected)
    {
        PlcValueTypes.TryParse(type, out PlcValueType t).Should().BeTrue();
        var tag = new TagDefinition("plc", 0, "tag", PlcAddress.Parse(address), t, count, WordOrder.LowWordFirst, Writable: true, HostLinkCommandSet.CMode);
        using JsonDocument value = JsonDocument.Parse(json);

        TagWriteOutcome outcome = await new TagWriter(new OpenLinks()).WriteAsync(tag, count == 1 ? value.RootElement[0] : value.RootElement, element: null, CancellationToken.None);

        outcome.Should().Be(TagWriteOutcome.Refused(expected));
    }

    [Fact]
    public void The_value_of_a_bit_group_is_read_without_throwing()
    {
        using JsonDocument value = JsonDocument.Parse("[true,false,true,true]");

        WriteValueParser.TryEncode(PlcValueType.Bit, 4, value.RootElement, WordOrder.LowWordFirst, out ushort[] words, out _).Should().BeTrue();

        words.Should().Equal(1, 0, 1, 1);
    }

    [Fact]
    public async Task A_command_the_gateway_fails_on_is_answered_as_failed_for_its_tag_without_the_exception()
    {
        var options = new MqttOptions { TopicPrefix = "test", Writes = { Enabled = true } };
        var gateway = new GatewayOptions();
        gateway.Links["plc"] = new LinkOptions();
        gateway.Links["plc"].Groups["level"] = new PollGroupOptions { Address = "D100", Type = "int16", Writable = true };
        var links = new OpenLinks();
        await using var line = new FailingStream();
        using var client = HostLinkClient.ForStream(line);
        links.LinkOpened("plc", client);
        var queue = new OutboundQueue(100);
        var topics = new MqttTopics("test", "gw");
        using var logs = new CapturingLoggerProvider();
        using var loggers = new LoggerFactory([logs]);
        var processor = new WriteCommandProcessor(
            options, topics, new TagCatalog(gateway), links, queue, new MqttMetrics(_services.GetRequiredService<IMeterFactory>(), queue),
            loggers.CreateLogger<WriteCommandProcessor>(), TimeProvider.System);

        WriteResultPayload? reply = await processor.ProcessAsync(new WriteCommand("test/plc/0/level/set", Encoding.UTF8.GetBytes("5"), null, null, false), CancellationToken.None);

        reply.Should().NotBeNull();
        reply!.Status.Should().Be("failed");
        reply.Tag.Should().Be("test/plc/0/level", "the reply names the tag's value topic");
        reply.Error.Should().Be($"the gateway failed on the command (its log has the details, event {MqttLog.Events.WriteCrashed}); read the value back to know whether it reached the PLC.");
        reply.Error.Should().NotContain(FailingStream.Secret).And.NotContain("Exception");
        queue.TryPeek(out OutboundMessage? sent).Should().BeTrue();
        sent!.Topic.Should().Be("test/plc/0/level/set/result");
        logs.WithEvent(MqttLog.Events.WriteCrashed).Should().ContainSingle().Which.Level.Should().Be(LogLevel.Error);
    }

    /// <summary>A line whose every read and write fails in a way no part of the gateway expects.</summary>
    private sealed class FailingStream() : PassThroughStream(Stream.Null)
    {
        public const string Secret = "an internal detail";

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
            => throw new NotSupportedException(Secret);

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
            => throw new NotSupportedException(Secret);
    }
}
