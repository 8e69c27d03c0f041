using System.CommandLine;
using System.Text.Json;
using OmronHostLink.Cli.Commands;

namespace OmronHostLink.Cli;

/// <summary>The <c>hostlink</c> command line: parses, runs one command, and returns its exit code.</summary>
internal static class CliApp
{
    /// <summary>How long a command may take to stop after Ctrl+C or SIGTERM before the process is ended.</summary>
    public static readonly TimeSpan StopGrace = TimeSpan.FromSeconds(5);

    /// <summary>Runs the command line <paramref name="args"/> with the given output streams.</summary>
    /// <param name="args">The arguments after the program name.</param>
    /// <param name="stdout">Results.</param>
    /// <param name="stderr">Errors, notes and, with <c>--verbose</c>, frames.</param>
    /// <param name="cancellationToken">Ctrl+C: stops <c>monitor</c> and <c>simulate</c> cleanly and cancels any exchange.</param>
    /// <returns>The exit code (see <see cref="ExitCodes"/>).</returns>
    internal static Task<int> RunAsync(string[] args, TextWriter stdout, TextWriter stderr, CancellationToken cancellationToken)
        => RunAsync(args, stdout, stderr, null, cancellationToken);

    /// <summary>Runs the command line with serial ports opened by <paramref name="serialPorts"/> (null: the system's).</summary>
    internal static async Task<int> RunAsync(string[] args, TextWriter stdout, TextWriter stderr, Func<Transports.SerialLineSettings, Transports.IHostLinkTransport>? serialPorts, CancellationToken cancellationToken)
    {
        var context = new CliContext(stdout, stderr, serialPorts);
        RootCommand root = BuildRoot(context);
        // No response files: Host Link frames start with '@', which would otherwise name a file to read arguments from.
        ParseResult parse = root.Parse(args, new ParserConfiguration { ResponseFileTokenReplacer = null });
        bool helpOrVersion = parse.Action is { ClearsParseErrors: true };
        if (parse.Errors.Count > 0 && !helpOrVersion)
        {
            string name = parse.CommandResult.Command is RootCommand ? "hostlink" : "hostlink " + parse.CommandResult.Command.Name;
            if (args.Contains("--json", StringComparer.Ordinal))
            {
                // A script that asked for JSON gets its one document even when the command line itself is wrong.
                string message = string.Join(" ", parse.Errors.Select(e => e.Message));
                stdout.WriteLine(JsonSerializer.Serialize(new ErrorDocument(new ErrorInfo("usage", null, message)), CliJsonContext.Console.ErrorDocument));
            }

            foreach (System.CommandLine.Parsing.ParseError error in parse.Errors)
            {
                stderr.WriteLine(error.Message);
            }

            stderr.WriteLine($"Run '{name} --help' for usage.");
            return ExitCodes.InvalidInput;
        }

        var invocation = new InvocationConfiguration
        {
            Output = stdout,
            Error = stderr,
            EnableDefaultExceptionHandler = false,
            ProcessTerminationTimeout = null,
        };
        if (parse.Action is System.CommandLine.Help.HelpAction)
        {
            var help = new StringWriter();
            int code = await parse.InvokeAsync(new InvocationConfiguration { Output = help, Error = stderr, EnableDefaultExceptionHandler = false, ProcessTerminationTimeout = null }, cancellationToken).ConfigureAwait(false);
            await stdout.WriteAsync(HelpText.MarkOptionalArguments(help.ToString(), parse.CommandResult.Command)).ConfigureAwait(false);
            return code;
        }

        return await parse.InvokeAsync(invocation, cancellationToken).ConfigureAwait(false);
    }

    /// <summary><c>hostlink help [command]</c>: the same as <c>--help</c>, for those who type it the other way round.</summary>
    private static Command HelpCommand(CliContext context)
    {
        var command = new Command("help", "Show the help of hostlink or of one command: hostlink help read.");
        var name = new Argument<string?>("command") { Description = "The command to explain (default: all commands).", Arity = ArgumentArity.ZeroOrOne };
        command.Add(name);
        command.SetAction(async (parse, cancellationToken) =>
        {
            string? target = parse.GetValue(name);
            Command root = parse.RootCommandResult.Command;
            if (target is not null && !root.Subcommands.Any(c => c.Name == target))
            {
                context.Error.WriteLine($"There is no command '{target}'; run 'hostlink help' for the list.");
                return ExitCodes.InvalidInput;
            }

            return await RunAsync(target is null ? ["--help"] : [target, "--help"], context.Out, context.Error, context.SerialPorts, cancellationToken).ConfigureAwait(false);
        });
        return command;
    }

    internal static RootCommand BuildRoot(CliContext context)
    {
        var root = new RootCommand("hostlink: talk to Omron PLCs over Host Link (C-mode and FINS): probe a line, read status and errors, read, write and monitor memory, change modes, decode captured frames, run a virtual PLC.");
        root.Add(context.Verbose);
        root.Add(PortsCommand.Create(context));
        root.Add(ScanCommand.Create(context));
        root.Add(DetectCommand.Create(context));
        root.Add(TestCommand.Create(context));
        root.Add(StatusCommand.Create(context));
        root.Add(ErrorsCommand.Create(context));
        root.Add(ModelCommand.Create(context));
        root.Add(ModeCommand.Create(context));
        root.Add(ReadCommand.Create(context));
        root.Add(WriteCommand.Create(context));
        root.Add(MonitorCommand.Create(context));
        root.Add(MonitorLineCommand.Create(context));
        root.Add(ExplainCommand.Create(context));
        root.Add(PlanCommand.Create(context));
        root.Add(RawCommand.Create(context));
        root.Add(SimulateCommand.Create(context));
        root.Add(DemoCommand.Create(context));
        root.Add(HelpCommand(context));
        return root;
    }
}
