using System.CommandLine;
using System.Globalization;

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
        var rmw = new Option<bool>("--read-modify-write") { Description = "Without --fins, write bits by reading the word, changing the bit and writing the word back (anything the PLC program writes in between is lost). With --fins bits are written directly." };
        Option<bool> json = CliContext.JsonOption();
        command.Add(address);
        command.Add(values);
        command.Add(kind);
        command.Add(rmw);
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

                Addresses.EnsureRange(target.AsWord(), ((target.Bit + bits.Length - 1) / 16) + 1, protocol, forWrite: true);
                await using HostLinkClient client = connection.CreateClient(parse, output, configure: o => o.AllowReadModifyWriteBits = useRmw);

                for (int i = 0; i < bits.Length; i++)
                {
                    await client.WriteBitAsync(addresses[i], bits[i], ct).ConfigureAwait(false);
                }

                summary = bits.Length == 1
                    ? $"Wrote {(bits[0] ? 1 : 0)} to {addresses[0]}."
                    : $"Wrote {bits.Length} bits to {addresses[0]}-{addresses[^1]}.";
                Report(output, target, k, v.Length, summary);
                return ExitCodes.Success;
            }

            if (target.IsBit)
            {
                throw new UsageException($"{target} names a bit; write it with --as bit, or give the word address {target.AsWord()}.");
            }

            ushort[] words = Encode(k, v, connection.WordOrder);
            Addresses.EnsureRange(target, words.Length, protocol, forWrite: true);
            await using (HostLinkClient client = connection.CreateClient(parse, output))
            {
                await client.WriteWordsAsync(target, words, ct).ConfigureAwait(false);
            }

            PlcAddress last = target.Offset(words.Length - 1);
            summary = words.Length == 1
                ? $"Wrote {Numbers.Hex(words[0])} ({words[0]}) to {target}."
                : $"Wrote {words.Length} words to {target}-{last}.";
            Report(output, target, k, words.Length, summary);
            return ExitCodes.Success;
        });
        return command;
    }

    private static void Report(OutputWriter output, PlcAddress target, PlcValueType kind, int count, string summary)
        => output.Result(
            w => w.WriteLine(summary),
            j =>
            {
                j.WriteStartObject();
                j.WriteString("address", target.ToString());
                j.WriteString("as", kind.Name());
                j.WriteNumber(kind == PlcValueType.Bit ? "bits" : "words", count);
                j.WriteBoolean("ok", true);
                j.WriteEndObject();
            });

    /// <summary>The words for the values, checked (nothing is sent when one is out of range).</summary>
    public static ushort[] Encode(PlcValueType kind, string[] values, WordOrder order)
    {
        if (kind == PlcValueType.String)
        {
            string text = string.Join(' ', values);
            if (text.Any(c => c > 0x7F))
            {
                throw new UsageException("The text must be ASCII.");
            }

            return PlcValueCodec.Encode([PlcValue.FromString(text)], order);
        }

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
