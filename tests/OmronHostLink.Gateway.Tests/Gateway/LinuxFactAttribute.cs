namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>A fact that needs Linux (systemd conventions, /proc, Unix datagram sockets); skipped with that reason elsewhere.</summary>
public sealed class LinuxFactAttribute : FactAttribute
{
    /// <summary>Sets <see cref="FactAttribute.Skip"/> on any other operating system.</summary>
    public LinuxFactAttribute()
    {
        if (!OperatingSystem.IsLinux())
        {
            Skip = "Needs Linux: the test plays systemd's part (a parent process named systemd, NOTIFY_SOCKET).";
        }
    }
}
