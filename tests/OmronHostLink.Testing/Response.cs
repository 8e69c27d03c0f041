using System.Text;
using FluentAssertions;
using OmronHostLink.Protocol;

namespace OmronHostLink.Testing;

/// <summary>A single response frame, checked for shape and FCS.</summary>
public sealed record Response(int Unit, string Header, string Text)
{
    /// <summary>The end code (first two characters of the text).</summary>
    public string EndCode => Text.Length >= 2 ? Text[..2] : string.Empty;

    /// <summary>The data after the end code.</summary>
    public string Data => Text.Length >= 2 ? Text[2..] : string.Empty;

    /// <summary>Parses a final (single) response frame; throws when the FCS or shape is wrong.</summary>
    public static Response Parse(string frame)
    {
        byte[] bytes = Encoding.ASCII.GetBytes(frame);
        FrameInfo info = FrameParser.ParseFirst(bytes);
        info.IsFinal.Should().BeTrue($"'{frame}' should be a final frame");
        return new Response(info.Unit, frame.Substring(3, 2), Encoding.ASCII.GetString(info.Text(bytes)));
    }

    /// <summary>The frame the PLC answers with only an end code.</summary>
    public static string Error(int unit, string header, string code) => RawHost.Command($"@{unit:D2}{header}{code}");
}
