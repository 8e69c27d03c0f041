namespace OmronHostLink.Testing;

/// <summary>Turnaround allowances for clients in tests.</summary>
public static class Allowances
{
    /// <summary>
    /// The turnaround allowance of a client whose PLC answers every frame (the simulator in process, over loopback TCP or
    /// a pty, or a scripted PLC) in a test that is not about deadlines. The line loses nothing, so the deadline only has
    /// to catch a lost answer; what it must not catch is the test process being paused. CI runs two test assemblies side
    /// by side on two cores, and each test host holds two thread-pool workers for its own use (the test platform's socket
    /// loop and the adapter's wait for the run), so an exchange can wait half a second or more for a thread to run it.
    /// Tests about deadlines set their own allowance or drive a fake clock.
    /// </summary>
    public static readonly TimeSpan LosslessLine = TimeSpan.FromSeconds(5);

    /// <summary><see cref="LosslessLine"/> as a configuration value or a console option.</summary>
    public const string LosslessLineText = "5s";
}
