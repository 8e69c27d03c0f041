using System.CommandLine;
using System.Globalization;
using System.Text.Json.Nodes;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>write</c>: writes words, numbers, text or bits.</summary>
internal static class WriteCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("write", "Write memory: one or more values from the address on, as one command. C-mode writes are refused in RUN mode (end code 01).");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        var address = new Argument<string>("address") { Description = "D100, CIO100.05, W30, H10, A448, T5, C7, E1_100." };
        var values = new Argument<string[]>("value") { Description = "Values: decimal or 0x-hex; float as 1.5; string as text; bit as 1/0, on/off, true/false.", Arity = ArgumentArity.OneOrMore };
        Option<string?> kind = ReadCommand.AsOption();
        var rmw = new Option<bool>("--read-modify-write") { Description = "Write bits with C-mode by reading the words they cover, changing the bits and writing the words back (one read, one write; anything the PLC program writes in between is lost). Without it, C-mode refuses bit writes: use --fins to write bits directly." };
        Option<int?> length = OptionValues.OptionalInteger("--length", "For --as string: the field's width in characters; the text is padded to fill it (default: the text and a NUL after it).", 1, 20000, "n");
        Option<string?> pad = OptionValues.OptionalChoice("--pad", "For --as string with --length: pad with nul (default) or space.", "nul|space", "nul", "space");
        Option<bool> json = CliContext.JsonOption();
        command.Add(address);
        command.Add(values);
        command.Add(kind);
        command.Add(rmw);
        command.Add(length);
        command.Add(pad);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            string a = parse.GetValue(address)!;
            string[] v = parse.GetValue(values) ?? [];
            if (v.FirstOrDefault(x => x.StartsWith("--", StringComparison.Ordinal)) is { } unknown)
            {
                throw new UsageException($"Unknown option '{unknown}'.");
            }
            PlcAddress target;
            if (v.Length > 1 && Addresses.TryJoin(a, v[0], out PlcAddress joined))
            {
                target = joined;
                v = v[1..];
            }
            else
            {
                target = Addresses.Parse(a);
            }

            string? kindText = parse.GetValue(kind);
            PlcValueType k = kindText is null ? target.IsBit ? PlcValueType.Bit : PlcValueType.Word : ValueKinds.Parse(kindText);
            HostLinkProtocol protocol = parse.GetValue(connection.Fins) ? HostLinkProtocol.Fins : HostLinkProtocol.CMode;
            bool useRmw = parse.GetValue(rmw);
            string summary;
            if (k == PlcValueType.Bit)
            {
                if (!target.IsBit)
                {
                    throw new UsageException($"{target} names a word; bits are written to a bit address such as {target}.05.");
                }

                bool[] bits = v.Select(ParseBit).ToArray();
                var addresses = new PlcAddress[bits.Length];
                for (int i = 0; i < bits.Length; i++)
                {
                    int n = target.Bit + i;
                    addresses[i] = target.AsWord().Offset(n / 16).WithBit(n % 16);
                }

                int wordsCovered = ((target.Bit + bits.Length - 1) / 16) + 1;
                Addresses.EnsureRange(target.AsWord(), wordsCovered, protocol, forWrite: true);
                if (protocol == HostLinkProtocol.CMode && !useRmw)
                {
                    // The library would fall back to FINS; the user chose C-mode, so say so rather than switch silently.
                    PlcAddress word = target.AsWord();
                    throw new UsageException(
                        $"C-mode has no bit write. Add --fins to write {Range(addresses)} with FINS (0102, one command), or --read-modify-write to read {Range(word, wordsCovered)}, change the bit{(bits.Length == 1 ? "" : "s")} and write the word{(wordsCovered == 1 ? "" : "s")} back (anything the PLC program writes there in between is lost).");
                }

                await using HostLinkClient client = connection.CreateClient(parse, output, configure: o => o.AllowReadModifyWriteBits = useRmw);
                await client.WriteBitsAsync(target, bits, ct).ConfigureAwait(false);

                summary = bits.Length == 1
                    ? $"Wrote {(bits[0] ? 1 : 0)} to {addresses[0]}."
                    : $"Wrote {bits.Length} bits to {addresses[0]}-{addresses[^1]}.";
                Report(output, client.UnitNumber, target, k, new JsonArray(bits.Select(b => (JsonNode?)JsonValue.Create(b)).ToArray()), null, summary);
                return ExitCodes.Success;
            }

            if (target.IsBit)
            {
                throw new UsageException($"{target} names a bit; write it with --as bit, or give the word address {target.AsWord()}.");
            }

            int? fieldLength = parse.GetValue(length);
            string? padding = parse.GetValue(pad);
            if (k != PlcValueType.String && (fieldLength is not null || padding is not null))
            {
                throw new UsageException("--length and --pad apply to --as string only.");
            }

            bool spaces = padding == "space";
            StringWrite? text = k == PlcValueType.String ? StringWrite.Create(string.Join(' ', v), fieldLength, spaces) : null;
            ushort[] words = text?.Words ?? Encode(k, v);
            Addresses.EnsureRange(target, words.Length, protocol, forWrite: true);
            int unit;
            await using (HostLinkClient client = connection.CreateClient(parse, output))
            {
                unit = client.UnitNumber;
                await client.WriteWordsAsync(target, words, ct).ConfigureAwait(false);
            }

            PlcAddress last = target.Offset(words.Length - 1);
            string range = words.Length == 1 ? target.ToString() : $"{target}-{last}";
            summary = text is not null
                ? $"Wrote \"{text.Text}\" to {range} ({text.Layout})."
                : words.Length == 1
                    ? $"Wrote {Numbers.Hex(words[0])} ({words[0]}) to {target}."
                    : $"Wrote {words.Length} words to {range}.";
            Report(output, unit, target, k, text is null ? ValuesOf(k, words) : [text.Text], words, summary);
            return ExitCodes.Success;
        });
        return command;
    }

    private static void Report(OutputWriter output, int unit, PlcAddress target, PlcValueType kind, JsonArray values, ushort[]? words, string summary)
    {
        if (output.IsJson)
        {
            output.Document(new WriteDocument(unit, target.ToString(), kind.Name(), values, words, Ok: true), CliJsonContext.Console.WriteDocument);
        }
        else
        {
            output.Line(summary);
        }
    }

    private static string Range(PlcAddress[] bits) => bits.Length == 1 ? bits[0].ToString() : $"{bits[0]}-{bits[^1]}";

    private static string Range(PlcAddress word, int words) => words == 1 ? word.ToString() : $"{word}-{word.Offset(words - 1)}";

    /// <summary>The values the words written hold, in their natural JSON type (what the PLC now has, decoded back).</summary>
    public static JsonArray ValuesOf(PlcValueType kind, ushort[] words)
    {
        var values = new JsonArray();
        switch (kind)
        {
            case PlcValueType.Int32:
            case PlcValueType.UInt32:
            case PlcValueType.Float:
                for (int i = 0; i + 1 < words.Length; i += 2)
                {
                    ReadOnlySpan<ushort> pair = words.AsSpan(i, 2);
                    values.Add(kind switch
                    {
                        PlcValueType.Int32 => JsonValue.Create(PlcWords.ReadInt32(pair)),
                        PlcValueType.UInt32 => JsonValue.Create(PlcWords.ReadUInt32(pair)),
                        _ => JsonValue.Create(PlcWords.ReadSingle(pair)),
                    });
                }

                break;
            default:
                foreach (ushort w in words)
                {
                    values.Add(kind switch
                    {
                        PlcValueType.Int16 => JsonValue.Create(PlcWords.ToInt16(w)),
                        PlcValueType.Bcd => JsonValue.Create(PlcWords.FromBcd(w)),
                        _ => JsonValue.Create(w),
                    });
                }

                break;
        }

        return values;
    }

    /// <summary>The words for numeric values, checked (nothing is sent when one is out of range); text is laid out by <see cref="StringWrite"/>.</summary>
    public static ushort[] Encode(PlcValueType kind, string[] values)
    {
        var words = new List<ushort>();
        Span<ushort> pair = stackalloc ushort[2];
        foreach (string v in values)
        {
            switch (kind)
            {
                case PlcValueType.Word:
                case PlcValueType.UInt16:
                    words.Add((ushort)Numbers.ParseInteger(v, 0, ushort.MaxValue, "The value"));
                    break;
                case PlcValueType.Int16:
                    long i16 = v.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
                        ? Numbers.ParseInteger(v, 0, ushort.MaxValue, "The int16 value")
                        : Numbers.ParseInteger(v, short.MinValue, short.MaxValue, "The int16 value");
                    words.Add(unchecked((ushort)i16));
                    break;
                case PlcValueType.Bcd:
                    words.Add(PlcWords.ToBcd((int)Numbers.ParseInteger(v, 0, PlcWords.MaxBcd, "The BCD value")));
                    break;
                case PlcValueType.Int32:
                    long i32 = v.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
                        ? Numbers.ParseInteger(v, 0, uint.MaxValue, "The int32 value")
                        : Numbers.ParseInteger(v, int.MinValue, int.MaxValue, "The int32 value");
                    PlcWords.WriteUInt32(unchecked((uint)i32), pair);
                    words.Add(pair[0]);
                    words.Add(pair[1]);
                    break;
                case PlcValueType.UInt32:
                    PlcWords.WriteUInt32((uint)Numbers.ParseInteger(v, 0, uint.MaxValue, "The uint32 value"), pair);
                    words.Add(pair[0]);
                    words.Add(pair[1]);
                    break;
                case PlcValueType.Float:
                    if (!float.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out float f) || !float.IsFinite(f))
                    {
                        throw new UsageException($"The float value '{v}' is not a finite number such as 1.5 or -2e3.");
                    }

                    PlcWords.WriteSingle(f, pair);
                    words.Add(pair[0]);
                    words.Add(pair[1]);
                    break;
            }
        }

        return words.ToArray();
    }

    public static bool ParseBit(string text) => text.Trim().ToLowerInvariant() switch
    {
        "1" or "on" or "true" or "set" => true,
        "0" or "off" or "false" or "reset" => false,
        _ => throw new UsageException($"The bit value '{text}' is not 1/0, on/off or true/false."),
    };
}
