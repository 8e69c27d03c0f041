namespace OmronHostLink.Gateway.Status;

/// <summary>
/// One frame as a link sent or took it: its direction, when, its bytes (CR included), and the unit and command it
/// belongs to — the frame's own for a first frame, else its exchange's (-1 and null when neither is known).
/// </summary>
/// <param name="ToPlc">True for a frame sent, false for one received.</param>
/// <param name="Time">When the link sent it or took it.</param>
/// <param name="Bytes">The frame, CR included.</param>
/// <param name="Unit">The unit.</param>
/// <param name="Header">The command's header (<c>RD</c>, <c>FA</c>, <c>**</c>).</param>
internal sealed record LinkFrame(bool ToPlc, DateTimeOffset Time, byte[] Bytes, int Unit, string? Header);
