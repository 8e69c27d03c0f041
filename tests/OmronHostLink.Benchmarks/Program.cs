using BenchmarkDotNet.Running;
using OmronHostLink.Benchmarks;

// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- wire [--runs N] [--baud N] [--no-plan | --plan-only | --tcp-only | --no-tcp] [--tcp-transactions N]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- serial [--rounds N] [--reads N]
// dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- --filter '*'
if (args.Length > 0 && args[0] == "wire")
{
    return await WireEfficiency.RunAsync(args[1..]);
}

if (args.Length > 0 && args[0] == "serial")
{
    return await SerialEfficiency.RunAsync(args[1..]);
}

BenchmarkSwitcher.FromAssembly(typeof(ProtocolBenchmarks).Assembly).Run(args);
return 0;
