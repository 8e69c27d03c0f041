using OmronHostLink.Gateway;

// Ctrl+C, SIGTERM (systemctl stop) and a Windows service stop all end here through the host's lifetime.
return await GatewayProgram.RunAsync(args, Console.Error);

/// <summary>
/// The entry point's class, declared so that it stays internal: with ASP.NET Core referenced, a source generator would
/// otherwise make it public (for test hosts), and the gateway's public types are its seven.
/// </summary>
internal sealed partial class Program;
