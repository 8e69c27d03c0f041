using System.CommandLine;
using System.Text;

namespace OmronHostLink.Cli;

/// <summary>What every command shares: the output streams and the global options, and how a command body is run.</summary>
internal sealed class CliContext
{
    public CliContext(TextWriter output, TextWriter error, Func<Transports.SerialLineSettings, Transports.IHostLinkTransport>? serialPorts = null)
    {
        Out = output;
        Error = error;
        SerialPorts = serialPorts ?? (settings => new Transports.SerialTransport(settings));
        Verbose = new Option<bool>("--verbose", "-v")
        {
            Description = "Print every frame sent and received, with direction and time (to stderr), and stack traces of errors.",
            Recursive = true,
        };
    }

    public TextWriter Out { get; }

    public TextWriter Error { get; }

    /// <summary>
    /// Opens a serial port at the given settings: the system's port, or in tests an emulated line that shows what other
    /// settings do (<c>detect</c> opens one per speed and format it tries).
    /// </summary>
    public Func<Transports.SerialLineSettings, Transports.IHostLinkTransport> SerialPorts { get; }

    /// <summary><c>--verbose</c>, on every command.</summary>
    public Option<bool> Verbose { get; }

    /// <summary>A new <c>--json</c> option for one command.</summary>
    public static Option<bool> JsonOption(string description = "Print the result as one JSON document.")
        => new("--json") { Description = description };

    /// <summary>
    /// Sets the command's action: runs <paramref name="body"/> and turns any exception into one clear sentence on stderr
    /// and its exit code (a stack trace only with <c>--verbose</c>).
    /// </summary>
    public void SetAction(Command command, Option<bool>? json, Func<ParseResult, OutputWriter, CancellationToken, Task<int>> body)
    {
        command.SetAction(async (parse, cancellationToken) =>
        {
            var output = new OutputWriter(Out, Error, json is not null && parse.GetValue(json), parse.GetValue(Verbose));
            try
            {
                return await body(parse, output, cancellationToken).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
            {
                output.Report(new ErrorInfo("cancelled", null, "Cancelled."));
                return ExitCodes.Failure;
            }
            catch (Exception e)
            {
                output.Report(ErrorOf(e));
                if (output.Verbose)
                {
                    output.Fail(e.ToString());
                }

                return ExitCodes.For(e);
            }
        });
    }

    /// <summary>The failure as the JSON error document describes it.</summary>
    public static ErrorInfo ErrorOf(Exception e) => new(KindOf(e), EndCodeOf(e), Describe(e));

    /// <summary><c>endCode</c>, <c>timeout</c>, <c>frame</c>, <c>connection</c>, <c>usage</c> or <c>other</c>.</summary>
    public static string KindOf(Exception e) => e switch
    {
        HostLinkEndCodeException or FinsEndCodeException => "endCode",
        HostLinkTimeoutException => "timeout",
        HostLinkFrameException => "frame",
        HostLinkConnectionException => "connection",
        UsageException or ArgumentException or NotSupportedException => "usage",
        _ => "other",
    };

    private static string? EndCodeOf(Exception e) => e switch
    {
        HostLinkEndCodeException c => c.EndCode.ToCode(),
        FinsEndCodeException f => f.EndCode.ToString(),
        _ => null,
    };

    /// <summary>One sentence for the user.</summary>
    public static string Describe(Exception e, ParseResult? parse = null)
    {
        string message = e switch
        {
            HostLinkEndCodeException { EndCode: EndCode.NotExecutableInRunMode } => e.Message.Trim().TrimEnd('.') + ". A CS/CJ takes C-mode writes in PROGRAM or MONITOR mode only; MONITOR keeps its program running: switch with 'hostlink mode monitor --yes' and the same --port or --tcp, or write with --fins.",
            UsageException => e.Message,
            ArgumentException => Addresses.InCliWords(Addresses.FirstSentence(e.Message)),
            NotSupportedException => Addresses.InCliWords(e.Message), // the model lacks what was asked for
            HostLinkException => e.Message,
            _ => $"{e.GetType().Name}: {e.Message}",
        };
        message = message.Trim();
        var sb = new StringBuilder(message);
        if (sb.Length > 0 && sb[^1] is not ('.' or '!' or '?'))
        {
            sb.Append('.');
        }

        return sb.ToString();
    }
}
