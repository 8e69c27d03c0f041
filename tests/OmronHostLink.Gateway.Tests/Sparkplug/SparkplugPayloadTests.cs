using System.Text.Json;
using System.Text.Json.Nodes;
using OmronHostLink.Gateway.Sparkplug;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>What the gateway's Sparkplug payloads say, as Eclipse Tahu's JavaScript library decodes them.</summary>
public sealed class SparkplugPayloadTests : IClassFixture<TahuCodecFixture>
{
    private static readonly DateTimeOffset Sent = new(2026, 11, 25, 12, 0, 0, TimeSpan.Zero);
    private static readonly DateTimeOffset Read = Sent.AddMilliseconds(-250);
    private readonly TahuCodec _tahu;

    public SparkplugPayloadTests(TahuCodecFixture fixture) => _tahu = fixture.Codec;

    private static JsonObject Metric(JsonObject payload, string name)
        => payload["metrics"]!.AsArray().Select(m => m!.AsObject()).Single(m => (string?)m["name"] == name);

    [Fact]
    public async Task A_node_birth_has_seq_0_the_bdSeq_and_the_rebirth_control()
    {
        JsonObject birth = await _tahu.DecodeAsync(SparkplugPayloads.NodeBirth(7, Sent));

        ((string?)birth["seq"]).Should().Be("0");
        ((string?)birth["timestamp"]).Should().Be(Sent.ToUnixTimeMilliseconds().ToString(System.Globalization.CultureInfo.InvariantCulture));
        JsonObject bdSeq = Metric(birth, "bdSeq");
        ((string?)bdSeq["type"]).Should().Be("Int64");
        ((string?)bdSeq["value"]).Should().Be("7");
        JsonObject rebirth = Metric(birth, "Node Control/Rebirth");
        ((string?)rebirth["type"]).Should().Be("Boolean");
        ((bool?)rebirth["value"]).Should().BeFalse();
    }

    [Fact]
    public async Task A_node_death_carries_the_bdSeq_and_no_seq()
    {
        JsonObject death = await _tahu.DecodeAsync(SparkplugPayloads.NodeDeath(7));

        death.ContainsKey("seq").Should().BeFalse("NDEATH is the MQTT will, registered before any sequence exists");
        ((string?)Metric(death, "bdSeq")["value"]).Should().Be("7");
    }

    public static TheoryData<PlcValueType, object, string, string> Values => new()
    {
        { PlcValueType.Int16, (short)-1234, "Int16", "-1234" },
        { PlcValueType.Word, (ushort)65535, "UInt16", "65535" },
        { PlcValueType.Bcd, 9999, "UInt16", "9999" },
        { PlcValueType.Int32, -2_000_000_000, "Int32", "-2000000000" },
        { PlcValueType.UInt32, 4_000_000_000u, "UInt32", "4000000000" },
        { PlcValueType.Float, 1.5f, "Float", "1.5" },
        { PlcValueType.Double, -2.25, "Double", "-2.25" },
        { PlcValueType.Bit, true, "Boolean", "true" },
        { PlcValueType.String, "PUMP 3", "String", "PUMP 3" },
    };

    [Theory]
    [MemberData(nameof(Values))]
    public async Task A_device_birth_names_each_metric_with_its_alias_type_value_and_read_time(PlcValueType tagType, object value, string type, string decoded)
    {
        var metric = new SparkplugMetric("tank", 42, SparkplugValues.DataTypeOf(tagType), "tank", -1, Writable: false);

        JsonObject birth = await _tahu.DecodeAsync(SparkplugPayloads.DeviceBirth(3, Sent, [new SparkplugMetricValue(metric, value, Read)]));

        ((string?)birth["seq"]).Should().Be("3");
        JsonObject m = Metric(birth, "tank");
        ((string?)m["alias"]).Should().Be("42");
        ((string?)m["type"]).Should().Be(type);
        ((string?)m["timestamp"]).Should().Be(Read.ToUnixTimeMilliseconds().ToString(System.Globalization.CultureInfo.InvariantCulture), "a metric's time is when the PLC was read");
        m["value"]!.ToJsonString().Trim('"').Should().Be(decoded);
    }

    [Fact]
    public async Task Data_goes_by_alias_and_a_value_that_is_not_good_carries_its_quality()
    {
        var good = new SparkplugMetric("level", 5, SparkplugDataType.Int16, "level", -1, false);
        var stale = new SparkplugMetric("speed", 6, SparkplugDataType.UInt16, "speed", -1, false);

        JsonObject data = await _tahu.DecodeAsync(SparkplugPayloads.Data(4, Sent,
        [
            new SparkplugMetricValue(good, (short)12, Read),
            new SparkplugMetricValue(stale, (ushort)7, Read, SparkplugQuality.Stale),
        ]));

        ((string?)data["seq"]).Should().Be("4");
        JsonArray metrics = data["metrics"]!.AsArray();
        metrics.Should().HaveCount(2);
        metrics.Select(m => m!["name"]).Should().AllSatisfy(n => n.Should().BeNull("data messages carry aliases only"));
        ((string?)metrics[0]!["alias"]).Should().Be("5");
        ((int?)metrics[0]!["value"]).Should().Be(12);
        metrics[0]!.AsObject().ContainsKey("properties").Should().BeFalse("a good value needs no quality");
        ((string?)metrics[1]!["alias"]).Should().Be("6");
        JsonObject quality = metrics[1]!["properties"]!["Quality"]!.AsObject();
        ((string?)quality["type"]).Should().Be("Int32");
        ((int?)quality["value"]).Should().Be(SparkplugQuality.Stale);
    }

    [Fact]
    public async Task A_metric_never_read_is_born_null()
    {
        var metric = new SparkplugMetric("level", 5, SparkplugDataType.Int16, "level", -1, false);
        JsonObject birth = await _tahu.DecodeAsync(SparkplugPayloads.DeviceBirth(1, Sent, [new SparkplugMetricValue(metric, null, Read, SparkplugQuality.Bad)]));
        JsonObject m = Metric(birth, "level");
        m["value"].Should().BeNull();
        ((int?)m["properties"]!["Quality"]!["value"]).Should().Be(SparkplugQuality.Bad);
    }

    [Fact]
    public async Task A_device_death_has_its_seq_and_no_metrics()
    {
        JsonObject death = await _tahu.DecodeAsync(SparkplugPayloads.DeviceDeath(9, Sent));
        ((string?)death["seq"]).Should().Be("9");
        (death["metrics"]?.AsArray() ?? []).Should().BeEmpty();
    }

    [Fact]
    public async Task Commands_encoded_by_Tahu_are_read_by_name_or_alias_in_the_tag_types_terms()
    {
        byte[] command = await _tahu.EncodeAsync(new
        {
            timestamp = 1,
            metrics = new object[]
            {
                new { name = "setpoint", type = "Int16", value = -300 },
                new { alias = 12, type = "Float", value = 2.5 },
                new { name = "run", type = "Boolean", value = true },
                new { name = "label", type = "String", value = "A\"B" },
                new { name = "total", type = "UInt32", value = 4_000_000 },
            },
        });

        IReadOnlyList<SparkplugCommandMetric> metrics = SparkplugCommandMetric.Parse(command)!;
        metrics.Should().HaveCount(5);
        Json(metrics[0], SparkplugDataType.Int16).Should().Be("-300");
        metrics[1].Name.Should().BeNull();
        metrics[1].Alias.Should().Be(12);
        Json(metrics[1], SparkplugDataType.Float).Should().Be("2.5");
        Json(metrics[2], SparkplugDataType.Boolean).Should().Be("true");
        Json(metrics[3], SparkplugDataType.String).Should().Be("\"A\\u0022B\"");
        Json(metrics[4], SparkplugDataType.UInt32).Should().Be("4000000");

        metrics[0].TryGetValue(SparkplugDataType.Boolean, out _, out string error).Should().BeFalse("a Boolean metric's value must be in boolean_value");
        error.Should().Contain("boolean_value");
    }

    [Fact]
    public void Bytes_that_are_not_a_payload_are_not_a_command()
        => SparkplugCommandMetric.Parse([0xFF, 0xFF, 0xFF]).Should().BeNull();

    private static string Json(SparkplugCommandMetric metric, SparkplugDataType type)
    {
        metric.TryGetValue(type, out JsonElement value, out string error).Should().BeTrue(error);
        return value.GetRawText();
    }
}

/// <summary>One node process for a test class.</summary>
public sealed class TahuCodecFixture : IDisposable
{
    public TahuCodec Codec { get; } = new();

    public void Dispose() => Codec.Dispose();
}
