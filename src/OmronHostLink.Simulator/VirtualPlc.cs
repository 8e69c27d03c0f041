namespace OmronHostLink.Simulator;

/// <summary>Placeholder until the simulator lands.</summary>
public sealed class VirtualPlc
{
}
