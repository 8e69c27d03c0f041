using System.Globalization;
using System.Text.Json;

namespace OmronHostLink.Simulator.Memory;

/// <summary>
/// Loads initial memory and state into a <see cref="VirtualPlc"/> from JSON.
/// </summary>
/// <remarks>
/// <para>The document is one object. Keys are addresses written the CX-Programmer way (see <see cref="PlcAddress.Parse"/>),
/// or one of the reserved keys below; keys are case-insensitive.</para>
/// <list type="bullet">
/// <item><c>"D100": [1, 2, 3]</c> — words from D100 on; <c>"CIO0": 255</c> — one word. A word is a number
/// 0–65535 (−32768…−1 are stored as 16-bit two's complement) or a string, <c>"0x00FF"</c> in hex or <c>"255"</c> in decimal.</item>
/// <item><c>"CIO10.03": true</c> — one bit (also <c>1</c>/<c>0</c>).</item>
/// <item><c>"T5": 100</c>, <c>"C7": [1, 2]</c> — timer and counter present values; <c>"E2_100": [...]</c> — EM bank 2.</item>
/// <item><c>"flags": {"T5": true, "C7": false}</c> — timer/counter completion flags.</item>
/// <item><c>"mode": "program" | "monitor" | "run"</c>; <c>"model": 48</c> or <c>"model": "30"</c> (hex string) — the MM model code;
/// <c>"falMessage": "PUMP FAULT"</c> — the MS FAL/FALS message (≤16 characters); <c>"errors": [w1, w2]</c> — the MF error words.</item>
/// </list>
/// <para>Example: <c>{"D100":[1,2,3],"CIO0":[255],"mode":"run","flags":{"T0":true}}</c>.</para>
/// </remarks>
public static class InitialMemory
{
    /// <summary>Applies a JSON document to <paramref name="plc"/>.</summary>
    /// <param name="plc">The PLC.</param>
    /// <param name="json">The document.</param>
    /// <exception cref="FormatException">The document does not follow the format; the message names the key.</exception>
    public static void Apply(VirtualPlc plc, string json)
    {
        ArgumentNullException.ThrowIfNull(plc);
        ArgumentNullException.ThrowIfNull(json);
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json, new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
        }
        catch (JsonException e)
        {
            throw new FormatException($"The initial memory is not valid JSON: {e.Message}", e);
        }

        using (document)
        {
            if (document.RootElement.ValueKind != JsonValueKind.Object)
            {
                throw new FormatException("The initial memory must be a JSON object of address keys.");
            }

            foreach (JsonProperty property in document.RootElement.EnumerateObject())
            {
                try
                {
                    ApplyProperty(plc, property);
                }
                catch (Exception e) when (e is ArgumentException or InvalidOperationException or FormatException)
                {
                    throw new FormatException($"Initial memory key '{property.Name}': {e.Message}", e);
                }
            }
        }
    }

    private static void ApplyProperty(VirtualPlc plc, JsonProperty property)
    {
        JsonElement value = property.Value;
        switch (property.Name.ToUpperInvariant())
        {
            case "MODE":
                plc.Mode = value.GetString()?.ToUpperInvariant() switch
                {
                    "PROGRAM" => PlcMode.Program,
                    "MONITOR" => PlcMode.Monitor,
                    "RUN" => PlcMode.Run,
                    _ => throw new FormatException("mode must be \"program\", \"monitor\" or \"run\"."),
                };
                return;
            case "MODEL":
                plc.ModelCode = value.ValueKind == JsonValueKind.String
                    ? byte.Parse(value.GetString()!, NumberStyles.HexNumber, CultureInfo.InvariantCulture)
                    : value.GetByte();
                return;
            case "FALMESSAGE":
                plc.FalMessage = value.ValueKind == JsonValueKind.Null ? null : value.GetString();
                return;
            case "ERRORS":
            {
                ushort[] words = Words(value);
                if (words.Length != 2)
                {
                    throw new FormatException("errors holds two words.");
                }

                plc.SetError(words[0], words[1]);
                return;
            }

            case "FLAGS":
                foreach (JsonProperty flag in value.EnumerateObject())
                {
                    PlcAddress a = PlcAddress.Parse(flag.Name);
                    if (a.Area is not (PlcArea.Timer or PlcArea.Counter))
                    {
                        throw new FormatException($"'{flag.Name}' is not a timer or counter.");
                    }

                    plc.SetFlag(a.Area, a.Word, Bool(flag.Value));
                }

                return;
        }

        PlcAddress address = PlcAddress.Parse(property.Name);
        if (address.IsBit)
        {
            plc.SetBit(address.Area, address.Word, address.Bit, Bool(value), address.Bank);
            return;
        }

        plc.WriteWords(address.Area, address.Word, Words(value), address.Bank);
    }

    private static bool Bool(JsonElement value) => value.ValueKind switch
    {
        JsonValueKind.True => true,
        JsonValueKind.False => false,
        JsonValueKind.Number => value.GetInt32() != 0,
        _ => throw new FormatException("A bit or flag is true/false or 1/0."),
    };

    private static ushort[] Words(JsonElement value)
    {
        if (value.ValueKind != JsonValueKind.Array)
        {
            return [Word(value)];
        }

        var words = new ushort[value.GetArrayLength()];
        int i = 0;
        foreach (JsonElement item in value.EnumerateArray())
        {
            words[i++] = Word(item);
        }

        return words;
    }

    private static ushort Word(JsonElement value)
    {
        int n;
        if (value.ValueKind == JsonValueKind.String)
        {
            string s = value.GetString()!.Trim();
            n = s.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
                ? int.Parse(s.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture)
                : int.Parse(s, NumberStyles.Integer, CultureInfo.InvariantCulture);
        }
        else if (value.ValueKind == JsonValueKind.Number)
        {
            n = value.GetInt32();
        }
        else
        {
            throw new FormatException($"A word is a number or a string, not {value.ValueKind}.");
        }

        if (n is < -32768 or > 65535)
        {
            throw new FormatException($"{n} does not fit a 16-bit word.");
        }

        return (ushort)n;
    }
}
