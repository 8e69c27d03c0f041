namespace OmronHostLink.Link;

/// <summary>Turns the complete response text of a transaction (every frame's text joined) into a result.</summary>
internal delegate TResult ResponseDecoder<TState, TResult>(ReadOnlySpan<byte> text, TState state);
