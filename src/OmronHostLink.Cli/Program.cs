using System.Runtime.InteropServices;
using OmronHostLink.Cli;

// Not disposed: a signal may still arrive while the process ends.
var cancellation = new CancellationTokenSource();

// Ctrl+C and SIGTERM (a service manager, kill) stop the command cleanly. Pressing Ctrl+C again while it stops does not
// kill the process (that would end monitor and simulate with exit code 130 instead of 0, depending on timing); a
// command that has not finished a few seconds after the first request is ended then.
Console.CancelKeyPress += (_, e) =>
{
    e.Cancel = true;
    Stop();
};

using PosixSignalRegistration terminate = PosixSignalRegistration.Create(PosixSignal.SIGTERM, context =>
{
    context.Cancel = true;
    Stop();
});

return await CliApp.RunAsync(args, Console.Out, Console.Error, cancellation.Token).ConfigureAwait(false);

void Stop()
{
    lock (cancellation)
    {
        if (cancellation.IsCancellationRequested)
        {
            return;
        }

        cancellation.Cancel();
    }

    _ = Task.Delay(CliApp.StopGrace).ContinueWith(
        _ =>
        {
            Console.Error.WriteLine($"Stopped: the command did not finish within {CliApp.StopGrace.TotalSeconds:0} s of the request to stop.");
            Environment.Exit(ExitCodes.Failure);
        },
        CancellationToken.None,
        TaskContinuationOptions.None,
        TaskScheduler.Default);
}
