using BenchmarkDotNet.Running;
using OmronHostLink.Benchmarks;
using OmronHostLink.Benchmarks.Demotion;
using OmronHostLink.Benchmarks.Fleet;
using OmronHostLink.Benchmarks.Scale;
using OmronHostLink.Benchmarks.Status;

// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- wire [--runs N] [--baud N] [--no-plan | --plan-only | --tcp-only | --no-tcp] [--tcp-transactions N]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- serial [--rounds N] [--reads N]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- scale [--links 1,10,50,100] [--seconds 60] [--tags 10]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- fleet [--gateways 20] [--links 5] [--seconds 60] [--kill-at 30] [--warmup 30] [--change-every 1s] [--poll 250ms]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- demotion [--units 8] [--interval 1s] [--window 60s] [--set Demotion:After=3]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- monitor [--rounds 20000]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- polling [--tags 100] [--baud 9600] [--interval 1s] [--seconds 60] [--before path/OmronHostLink.Gateway.dll]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- mixed [--links 4] [--units 2] [--baud 38400] [--window 10m] [--warmup 30s]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- status [--tags 1000] [--links 4] [--interval 1s] [--seconds 60] [--warmup 20] [--rounds 3] [--browsers 3]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- --filter '*'
if (args.Length > 0 && args[0] == "wire")
{
    return await WireEfficiency.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "serial")
{
    return await SerialEfficiency.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "scale")
{
    return await ScaleBenchmark.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "fleet")
{
    return await FleetRun.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "monitor")
{
    return await MonitorThroughput.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "polling")
{
    return await OmronHostLink.Benchmarks.Polling.PollingMeasurement.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "mixed")
{
    return await OmronHostLink.Benchmarks.Polling.MixedScanMeasurement.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "demotion")
{
    return await DemotionMeasurement.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "status")
{
    return await StatusPageMeasurement.RunAsync(args[1..]);
}

BenchmarkSwitcher.FromAssembly(typeof(ProtocolBenchmarks).Assembly).Run(args);
return 0;
