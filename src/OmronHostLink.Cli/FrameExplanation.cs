using System.Text.Json.Serialization;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli;

/// <summary>
/// A decoded frame: what <c>explain</c> prints, and, property for property in this order, its JSON document (written by
/// <see cref="ExplainJsonContext"/>).
/// </summary>
internal sealed class FrameExplanation : OmronHostLink.Protocol.ICommandFields
{
    /// <summary><see cref="DirectionFrom"/>: the user said which way the frame goes.</summary>
    public const string FromOption = "option";

    /// <summary><see cref="DirectionFrom"/>: the frame can only go one way.</summary>
    public const string FromShape = "shape";

    /// <summary><see cref="DirectionFrom"/>: the frame is well-formed both ways; explained as a command.</summary>
    public const string FromAmbiguous = "ambiguous";

    /// <summary><see cref="DirectionFrom"/>: nothing tells; explained as a command.</summary>
    public const string FromDefault = "default";

    public bool Valid => Problems.Count == 0;

    public required string Frame { get; init; }

    public string Direction => IsResponse ? "response" : "command";

    /// <summary>How the direction was decided: <see cref="FromOption"/>, <see cref="FromShape"/>, <see cref="FromAmbiguous"/> or <see cref="FromDefault"/>.</summary>
    public string DirectionFrom { get; set; } = FromOption;

    public int? Unit { get; set; }

    public string? Header { get; set; }

    public string? Name { get; set; }

    public string? EndCode { get; set; }

    public string? EndCodeMeaning { get; set; }

    /// <summary>The FCS found and expected; null when the frame has no room for one.</summary>
    public FcsExplanation? Fcs => FcsFound is null
        ? null
        : new(FcsExpected!, FcsFound, string.Equals(FcsFound, FcsExpected, StringComparison.Ordinal), IsLowercaseOf(FcsFound, FcsExpected!));

    /// <summary>True for a frame that ends with <c>*</c>CR (or is read as one); false for a non-final frame.</summary>
    public bool Final { get; set; } = true;

    public string? Text { get; set; }

    /// <summary>The data after the end code of an answer (written for answers only).</summary>
    public string? Data { get; set; }

    /// <summary>Decoded fields in order; values are string, long, bool, string[], long[], bool[], <see cref="FinsAddressField"/>, <see cref="FinsAddressField"/>[] or null.</summary>
    public OrderedDictionary<string, object?> Fields { get; } = [];

    public List<string> Notes { get; } = [];

    public List<string> Problems { get; } = [];

    [JsonIgnore]
    public bool IsResponse { get; set; }

    [JsonIgnore]
    public string? FcsExpected { get; set; }

    [JsonIgnore]
    public string? FcsFound { get; set; }

    public void Field(string name, object? value) => Fields.Add(name, value);

    /// <inheritdoc/>
    public void Note(string note) => Notes.Add(note);

    /// <inheritdoc/>
    public void Problem(string problem) => Problems.Add(problem);

    /// <summary>Whether <paramref name="found"/> differs from <paramref name="expected"/> (upper case) only in letter case.</summary>
    public static bool IsLowercaseOf(string found, string expected)
        => !string.Equals(found, expected, StringComparison.Ordinal) && string.Equals(found, expected, StringComparison.OrdinalIgnoreCase);
}

/// <summary>The FCS of an explained frame; <see cref="Lowercase"/> when it is right but written in lower case.</summary>
internal sealed record FcsExplanation(string Expected, string Found, bool Ok, bool Lowercase);
