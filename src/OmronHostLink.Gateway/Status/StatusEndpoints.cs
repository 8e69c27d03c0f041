using System.Net.ServerSentEvents;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// The page's routes, every one a <c>GET</c> (and <c>HEAD</c>): each view as one JSON document and as a stream of
/// server-sent events. None changes anything in the gateway or a PLC; a link's trace stream takes the link's frames
/// while it is open.
/// </summary>
internal static class StatusEndpoints
{
    private static readonly string[] ReadMethods = [HttpMethods.Get, HttpMethods.Head];

    /// <summary>Maps the routes onto <paramref name="routes"/>.</summary>
    public static void Map(IEndpointRouteBuilder routes, LinesView lines, TagBoard tags, OutputsView outputs, LineTraces traces, StatusStreams streams)
    {
        routes.MapRead("/api/lines", () => TypedResults.Json(lines.Snapshot(), StatusJsonContext.Default.LinesDocument));
        routes.MapRead("/api/lines/events", (HttpRequest request, CancellationToken aborted) => Events(request, () => streams.Lines(aborted)));

        routes.MapRead("/api/tags", () => TypedResults.Json(new TagsDocument { Tags = tags.All() }, StatusJsonContext.Default.TagsDocument));
        routes.MapRead("/api/tags/events", (HttpRequest request, CancellationToken aborted) => Events(request, () => streams.Tags(aborted)));

        routes.MapRead("/api/outputs", () => TypedResults.Json(outputs.Snapshot(), StatusJsonContext.Default.OutputsDocument));
        routes.MapRead("/api/outputs/events", (HttpRequest request, CancellationToken aborted) => Events(request, () => streams.Outputs(aborted)));

        // The links that can be traced; a link's frames kept so far (taking none); the live trace.
        routes.MapRead("/api/trace", () => TypedResults.Json(traces.Links, StatusJsonContext.Default.IReadOnlyListString));
        routes.MapRead("/api/trace/{link}", IResult (string link, long? after) => traces.Trace(link) is { } trace
            ? Frames(link, trace, after ?? 0)
            : NoLink(link));
        routes.MapRead("/api/trace/{link}/events", IResult (HttpRequest request, string link, long? after, CancellationToken aborted) => traces.Trace(link) is null
            ? NoLink(link)
            : Events(request, () => streams.Trace(link, after ?? 0, aborted)));
    }

    private static void MapRead(this IEndpointRouteBuilder routes, string pattern, Delegate handler) => routes.MapMethods(pattern, ReadMethods, handler);

    /// <summary>
    /// A stream of events; for <c>HEAD</c> its headers alone: a stream answered to <c>HEAD</c> would never end, and
    /// hold the connection its client takes back for its next request.
    /// </summary>
    private static IResult Events(HttpRequest request, Func<IAsyncEnumerable<SseItem<string>>> events)
        => HttpMethods.IsHead(request.Method)
            ? TypedResults.Text(string.Empty, "text/event-stream")
            : TypedResults.ServerSentEvents(events());

    private static IResult Frames(string link, LineTrace trace, long after)
    {
        (List<TracedFrame> frames, long lost) = trace.After(after);
        return TypedResults.Json(StatusStreams.Document(link, frames, lost), StatusJsonContext.Default.TraceDocument);
    }

    private static IResult NoLink(string link) => TypedResults.Text($"No link {link} is configured.\n", "text/plain; charset=utf-8", statusCode: StatusCodes.Status404NotFound);
}
