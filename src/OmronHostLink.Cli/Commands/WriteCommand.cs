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
            HostLinkCommandSet protocol = parse.GetValue(connection.Fins) ? HostLinkCommandSet.Fins : HostLinkCommandSet.CMode;
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
                if (protocol == HostLinkCommandSet.CMode && !useRmw)
                {
                    // The library refuses it too (C-mode has no bit write); said here in the console's options, before connecting.
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
            ushort[] words = text?.Words ?? Encode(k, v, connection.WordOrder);
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
            Report(output, unit, target, k, text is null ? ValuesOf(k, words, connection.WordOrder) : [text.Text], words, summary);
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
    public static JsonArray ValuesOf(PlcValueType kind, ushort[] words, WordOrder order)
    {
        var values = new JsonArray();
        foreach (PlcValue value in PlcValueCodec.DecodeValues(kind, words, words.Length / kind.WordsPerValue(), order))
        {
            values.Add(value.Type switch
            {
                PlcValueType.Word or PlcValueType.UInt16 => JsonValue.Create(value.ToUInt16()),
                PlcValueType.Int16 => JsonValue.Create(value.ToInt16()),
                PlcValueType.Int32 or PlcValueType.Bcd or PlcValueType.Bcd32 => JsonValue.Create(value.ToInt32()),
                PlcValueType.UInt32 => JsonValue.Create(value.ToUInt32()),
                PlcValueType.Float => JsonValue.Create(value.ToSingle()),
                PlcValueType.Double => JsonValue.Create(value.ToDouble()),
                _ => JsonValue.Create(value.ToString()),
            });
        }

        return values;
    }

    /// <summary>The words for numeric values, checked (nothing is sent when one is out of range); text is laid out by <see cref="StringWrite"/>.</summary>
    public static ushort[] Encode(PlcValueType kind, string[] values, WordOrder order)
    {
        return PlcValueCodec.Encode(values.Select(v => Parse(kind, v)).ToArray(), order);
    }

    /// <summary>One value typed by the user: decimal or 0x-hex integers (hex gives the raw bits of signed types), finite REAL.</summary>
    private static PlcValue Parse(PlcValueType kind, string v) => kind switch
    {
        PlcValueType.Word => PlcValue.FromWord((ushort)Numbers.ParseInteger(v, 0, ushort.MaxValue, "The value")),
        PlcValueType.UInt16 => PlcValue.FromUInt16((ushort)Numbers.ParseInteger(v, 0, ushort.MaxValue, "The value")),
        PlcValueType.Int16 => PlcValue.FromInt16(unchecked((short)(v.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
            ? Numbers.ParseInteger(v, 0, ushort.MaxValue, "The int16 value")
            : Numbers.ParseInteger(v, short.MinValue, short.MaxValue, "The int16 value")))),
        PlcValueType.Bcd => PlcValue.FromBcd((int)Numbers.ParseInteger(v, 0, PlcWords.MaxBcd, "The BCD value")),
        PlcValueType.Int32 => PlcValue.FromInt32(unchecked((int)(v.StartsWith("0x", StringComparison.OrdinalIgnoreCase)
            ? Numbers.ParseInteger(v, 0, uint.MaxValue, "The int32 value")
            : Numbers.ParseInteger(v, int.MinValue, int.MaxValue, "The int32 value")))),
        PlcValueType.UInt32 => PlcValue.FromUInt32((uint)Numbers.ParseInteger(v, 0, uint.MaxValue, "The uint32 value")),
        PlcValueType.Float => float.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out float f) && float.IsFinite(f)
            ? PlcValue.FromSingle(f)
            : throw new UsageException($"The float value '{v}' is not a finite number such as 1.5 or -2e3."),
        PlcValueType.Double => double.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) && double.IsFinite(d)
            ? PlcValue.FromDouble(d)
            : throw new UsageException($"The double value '{v}' is not a finite number such as 1.5 or -2e3."),
        _ => throw new UsageException($"--as {kind.Name()} values cannot be written as words."),
    };

    public static bool ParseBit(string text) => text.Trim().ToLowerInvariant() switch
    {
        "1" or "on" or "true" or "set" => true,
        "0" or "off" or "false" or "reset" => false,
        _ => throw new UsageException($"The bit value '{text}' is not 1/0, on/off or true/false."),
    };
}
