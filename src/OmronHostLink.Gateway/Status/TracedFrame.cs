using System.Globalization;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Explain;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// A frame in a link's trace: its number, the frame, and for an answer the time since the frame before it went out.
/// It is explained (as <c>hostlink explain</c> does, by the library's <see cref="FrameExplainer"/>) when a page first
/// shows it, not on the link's path, and once however many pages show it.
/// </summary>
/// <param name="seq">Its number in the link's trace, from 1.</param>
/// <param name="frame">The frame.</param>
/// <param name="latency">For a frame from the PLC: the time since the link's last frame out.</param>
internal sealed class TracedFrame(long seq, LinkFrame frame, TimeSpan? latency)
{
    private TraceFrameView? _view;

    /// <summary>Its number in the link's trace.</summary>
    public long Seq { get; } = seq;

    /// <summary>The frame.</summary>
    public LinkFrame Frame { get; } = frame;

    /// <summary>The frame as the page shows it, explained.</summary>
    public TraceFrameView View => _view ??= Explain();

    private TraceFrameView Explain()
    {
        string time = Frame.Time.UtcDateTime.ToString("yyyy-MM-dd'T'HH:mm:ss.ffffff'Z'", CultureInfo.InvariantCulture);
        string text = FrameText.Printable(Frame.Bytes);
        int? unit = Frame.Unit >= 0 ? Frame.Unit : null;
        if (Frame.Bytes is [(byte)'\r'])
        {
            // The bare CR of a multi-frame exchange: the receiver asks for the next frame.
            return Plain(time, text, unit, Frame.ToPlc ? "CR: send the answer's next frame" : "CR: the PLC asks for the command's next frame", [], [], []);
        }

        FrameExplanation x;
        try
        {
            x = FrameExplainer.Explain(Frame.Bytes, response: !Frame.ToPlc);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return Plain(time, text, unit, null, [], [], ["This frame cannot be explained: " + e.Message]);
        }

        return new TraceFrameView
        {
            Seq = Seq,
            Time = time,
            Dir = Frame.ToPlc ? "out" : "in",
            Unit = x.Unit ?? unit,
            Header = x.Header ?? Frame.Header,
            Name = x.Name,
            EndCode = x.EndCode,
            EndCodeMeaning = x.EndCodeMeaning,
            LatencyMs = latency?.TotalMilliseconds,
            Text = text,
            Fields = x.Fields.Select(f => $"{f.Key}: {Display(f.Value)}").ToList(),
            Notes = x.Notes,
            Problems = x.Problems,
        };
    }

    private TraceFrameView Plain(string time, string text, int? unit, string? name, List<string> fields, List<string> notes, List<string> problems) => new()
    {
        Seq = Seq,
        Time = time,
        Dir = Frame.ToPlc ? "out" : "in",
        Unit = unit,
        Header = Frame.Header,
        Name = name,
        LatencyMs = latency?.TotalMilliseconds,
        Text = text,
        Fields = fields,
        Notes = notes,
        Problems = problems,
    };

    /// <summary>A field's value as text: numbers and flags as they are, lists in brackets, FINS addresses described.</summary>
    private static string Display(object? value) => value switch
    {
        null => "—",
        string s => s,
        bool b => b ? "true" : "false",
        IFormattable f => f.ToString(null, CultureInfo.InvariantCulture),
        System.Collections.IEnumerable list => "[" + string.Join(", ", list.Cast<object?>().Select(Display)) + "]",
        _ => value.ToString() ?? "",
    };
}
