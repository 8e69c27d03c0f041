using System.Buffers;
using System.Globalization;
using System.Text;
using System.Text.Json;
using OmronHostLink.Protocol;

namespace OmronHostLink.Cli;

/// <summary>
/// Where a command's results go: human-readable lines, or exactly one compact JSON document per result (one per line).
/// Errors and diagnostics (frames with <c>--verbose</c>) go to the error writer, so JSON output stays parseable.
/// </summary>
internal sealed class OutputWriter
{
    private static readonly JsonWriterOptions JsonOptions = new()
    {
        Indented = false,

        // Console output, not HTML: keep quotes and apostrophes readable.
        Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
    };
    private readonly object _gate = new();

    public OutputWriter(TextWriter output, TextWriter error, bool json = false, bool verbose = false)
    {
        Out = output;
        Error = error;
        IsJson = json;
        Verbose = verbose;
    }

    public TextWriter Out { get; }

    public TextWriter Error { get; }

    /// <summary>Whether results are written as JSON.</summary>
    public bool IsJson { get; }

    /// <summary>Whether frames and stack traces are shown.</summary>
    public bool Verbose { get; }

    /// <summary>Writes a line of human output (nothing in JSON mode).</summary>
    public void Line(string text = "")
    {
        if (!IsJson)
        {
            lock (_gate)
            {
                Out.WriteLine(text);
            }
        }
    }

    /// <summary>Writes one result: <paramref name="human"/> in human mode, one JSON document in JSON mode.</summary>
    public void Result(Action<TextWriter> human, Action<Utf8JsonWriter> json)
    {
        lock (_gate)
        {
            if (IsJson)
            {
                Out.WriteLine(ToJson(json));
            }
            else
            {
                human(Out);
            }
        }
    }

    /// <summary>Writes a JSON document to a string (no reflection: the writer is driven by hand).</summary>
    public static string ToJson(Action<Utf8JsonWriter> write)
    {
        var buffer = new ArrayBufferWriter<byte>(256);
        using (var writer = new Utf8JsonWriter(buffer, JsonOptions))
        {
            write(writer);
        }

        return Encoding.UTF8.GetString(buffer.WrittenSpan);
    }

    /// <summary>
    /// Reports a failure: its sentence on the error writer, and in JSON mode also the error document on the output, so
    /// that a script reading stdout always gets one document.
    /// </summary>
    public void Report(ErrorInfo error)
    {
        lock (_gate)
        {
            if (IsJson)
            {
                Out.WriteLine(JsonSerializer.Serialize(new ErrorDocument(error), CliJsonContext.Console.ErrorDocument));
            }

            Error.WriteLine(error.Message);
        }
    }

    /// <summary>Writes a source-generated JSON document as one line (JSON mode only).</summary>
    public void Document<T>(T document, System.Text.Json.Serialization.Metadata.JsonTypeInfo<T> type)
    {
        if (IsJson)
        {
            lock (_gate)
            {
                Out.WriteLine(JsonSerializer.Serialize(document, type));
            }
        }
    }

    /// <summary>Writes an error sentence to the error writer.</summary>
    public void Fail(string message)
    {
        lock (_gate)
        {
            Error.WriteLine(message);
        }
    }

    /// <summary>Writes a note to the error writer (progress that is not a result).</summary>
    public void Note(string message)
    {
        lock (_gate)
        {
            Error.WriteLine(message);
        }
    }

    /// <summary>The frame observer for <c>--verbose</c>: every frame with its direction and time, on the error writer.</summary>
    public Action<bool, ReadOnlyMemory<byte>> FrameTrace(TextWriter? to = null)
        => (sent, frame) =>
        {
            string line = FormatFrame(sent, frame.Span, DateTime.Now);
            lock (_gate)
            {
                (to ?? Error).WriteLine(line);
            }
        };

    /// <summary><c>12:34:56.789 &gt;&gt; @00RD0000001057*\r</c>.</summary>
    public static string FormatFrame(bool sent, ReadOnlySpan<byte> frame, DateTime time)
        => time.ToString("HH:mm:ss.fff", CultureInfo.InvariantCulture) + (sent ? " >> " : " << ") + FrameText.Printable(frame);
}
