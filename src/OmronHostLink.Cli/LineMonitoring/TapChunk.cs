namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// Bytes one read of a tapped port returned, with the Stopwatch time the read returned and the reader's watermark; or,
/// with no bytes, the watermark alone (the port was found quiet).
/// </summary>
/// <param name="Source">Which port: 0 for the one port (or the port that hears the host), 1 for the port that hears the PLC.</param>
/// <param name="Bytes">The bytes; empty when the chunk only carries <paramref name="Clear"/>.</param>
/// <param name="Ticks">Stopwatch time the read returned: no byte of the chunk arrived later.</param>
/// <param name="Clear">
/// The watermark: every byte that reached the port before this Stopwatch time has been read (it is in this chunk or an
/// earlier one), so every byte of a later chunk arrived at or after it. 0 when the reader cannot say.
/// </param>
internal readonly record struct TapChunk(int Source, byte[] Bytes, long Ticks, long Clear);
