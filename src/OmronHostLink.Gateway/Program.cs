using OmronHostLink.Gateway;

// Ctrl+C, SIGTERM (systemctl stop) and a Windows service stop all end here through the host's lifetime.
return await GatewayProgram.RunAsync(args, Console.Error);
