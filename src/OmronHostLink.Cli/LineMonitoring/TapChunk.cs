namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>Bytes one read of a tapped port returned, with the Stopwatch time the read returned.</summary>
/// <param name="Source">Which port: 0 for the one port (or the port that hears the host), 1 for the port that hears the PLC.</param>
/// <param name="Bytes">The bytes.</param>
/// <param name="Ticks">Stopwatch timestamp of their arrival.</param>
internal readonly record struct TapChunk(int Source, byte[] Bytes, long Ticks);
