using System.CommandLine;
using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Cli;
using OmronHostLink.DependencyInjection;
using OmronHostLink.Tests.DependencyInjection;

namespace OmronHostLink.Tests.Settings;

/// <summary>
/// The same text is the same time, or the same refusal, wherever a duration is written: the DI package's configuration,
/// <c>AddHostLinkClient(..., Action)</c> and the console's options (the gateway's configuration: OmronHostLink.Gateway.Tests).
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

    [Theory]
    [MemberData(nameof(Texts))]
    public async Task DI_configuration_reads_it_the_same(string text, long? ticks)
    {
        string json = $$"""{ "HostLink": { "Clients": { "line1": { "Tcp": { "Host": "127.0.0.1", "Port": 9, "ConnectTimeout": "{{text}}" } } } } }""";
        void Register(IServiceCollection services, IConfiguration configuration) => services.AddHostLinkClients(configuration.GetSection("HostLink:Clients"));

        if (ticks is { } t)
        {
            await using JsonHost host = JsonHost.Build(json, Register);
            await host.Host.StartAsync();
            host.Services.GetRequiredService<IOptionsMonitor<HostLinkClientSettings>>().Get("line1").Tcp.ConnectTimeout
                .Should().Be(TimeSpan.FromTicks(t));
        }
        else
        {
            IReadOnlyList<string> failures = await JsonHost.StartFailuresAsync(json, Register);
            failures.Should().Equal($"HostLink:Clients:line1:Tcp:ConnectTimeout: {Refusal(text)}");
        }
    }

    [Theory]
    [MemberData(nameof(Texts))]
    public async Task AddHostLinkClient_with_an_action_reads_it_the_same(string text, long? ticks)
    {
        await using JsonHost host = JsonHost.Build("{}", (services, _) => services.AddHostLinkClient("line1", o =>
        {
            o.Tcp.Host = "127.0.0.1";
            o.Tcp.Port = 9;
            o.Tcp.ConnectTimeout = Duration.Parse(text);
        }));
        Exception? failure = await Record.ExceptionAsync(() => host.Host.StartAsync());

        if (ticks is { } t)
        {
            failure.Should().BeNull();
            host.Services.GetRequiredService<IOptionsMonitor<HostLinkClientSettings>>().Get("line1").Tcp.ConnectTimeout
                .Should().Be(TimeSpan.FromTicks(t));
        }
        else
        {
            failure.Should().BeOfType<FormatException>().Which.Message.Should().Be(Refusal(text));
        }
    }

    [Theory]
    [MemberData(nameof(Texts))]
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
            parse.Errors.Select(e => e.Message).Should().Equal($"--interval: {Refusal(text)}.");
        }
    }

    private static string Refusal(string text)
    {
        Duration.TryParse(text, out _, out string? error).Should().BeFalse();
        return error!;
    }
}
