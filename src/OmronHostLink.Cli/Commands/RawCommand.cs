using System.CommandLine;
using System.Text;
using System.Text.Json;
using OmronHostLink.Protocol;

namespace OmronHostLink.Cli.Commands;

/// <summary><c>raw</c>: sends a command as typed (the FCS and terminator are added) and prints the answer frames as received.</summary>
internal static class RawCommand
{
    public static Command Create(CliContext context)
    {
        var command = new Command("raw", "Send a raw command: header and text as typed, after '@' and the unit number; the FCS, '*' and CR are added. Prints the answer frames as received. Exit 3 when the answer carries an error end code.");
        var connection = new ConnectionOptions();
        connection.AddTo(command);
        var text = new Argument<string>("text") { Description = "Header and text, for example MS or RD00000010 (no @, *, CR or unit number)." };
        Option<bool> json = CliContext.JsonOption();
        command.Add(text);
        command.Add(json);
        context.SetAction(command, json, async (parse, output, ct) =>
        {
            string t = parse.GetValue(text)!;
            Validate(t);
            string header = t[..2];
            await using HostLinkClient client = connection.CreateClient(parse, output);
            var sent = new List<string>();
            var received = new List<string>();
            Action<bool, ReadOnlyMemory<byte>>? trace = client.FrameObserver;
            client.FrameObserver = (isSent, frame) =>
            {
                trace?.Invoke(isSent, frame);
                (isSent ? sent : received).Add(FrameText.Printable(frame.Span));
            };

            byte[] answer;
            try
            {
                answer = await client.ExchangeRawAsync(t, expectsResponse: header != "XZ", ct).ConfigureAwait(false);
            }
            catch (HostLinkEndCodeException e)
            {
                return Refused(output, client.UnitNumber, sent, received, null, e);
            }

            string answerText = Encoding.ASCII.GetString(answer);
            if (header is not ("TS" or "XZ") && answer.Length >= 2 && HexAscii.TryParseByte(answer.AsSpan(0, 2), out byte code) && code != 0)
            {
                return Refused(output, client.UnitNumber, sent, received, answerText, new HostLinkEndCodeException((EndCode)code, header, client.UnitNumber));
            }

            Print(output, client.UnitNumber, sent, received, answerText, null);
            return ExitCodes.Success;
        });
        return command;
    }

    /// <summary>Refuses text that would break framing (nothing is sent).</summary>
    public static void Validate(string text)
    {
        if (text.Length < 2)
        {
            throw new UsageException("A raw command starts with a two-character header, such as MS or RD.");
        }

        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            string? why = c switch
            {
                '*' => "'*' (the FCS and terminator are added for you)",
                '@' => "'@' (the '@' and unit number are added for you; use --unit)",
                '\r' or '\n' => "a line break (the CR is added for you)",
                < ' ' or > '~' => $"the character 0x{(int)c:X2}, which is not printable ASCII",
                _ => null,
            };
            if (why is not null)
            {
                throw new UsageException($"The raw text may not contain {why}; found at position {i}.");
            }
        }

        if (text.Length + 7 > FrameWriter.MaxFirstFrameLength)
        {
            throw new UsageException($"The raw text is {text.Length} characters; with '@', the unit, the FCS, '*' and CR it must fit one {FrameWriter.MaxFirstFrameLength}-character frame (at most {FrameWriter.MaxFirstFrameLength - 7} characters).");
        }
    }

    /// <summary>An answer with an error end code: the frames as received and, in the same JSON document, the error.</summary>
    private static int Refused(OutputWriter output, int unit, List<string> sent, List<string> received, string? text, HostLinkEndCodeException e)
    {
        ErrorInfo error = CliContext.ErrorOf(e);
        Print(output, unit, sent, received, text, error);
        output.Fail(error.Message);
        return ExitCodes.EndCode;
    }

    private static void Print(OutputWriter output, int unit, List<string> sent, List<string> received, string? text, ErrorInfo? error)
        => output.Result(
            w =>
            {
                if (received.Count == 0)
                {
                    w.WriteLine("(no answer expected)");
                }

                foreach (string frame in received)
                {
                    w.WriteLine(frame);
                }
            },
            j =>
            {
                j.WriteStartObject();
                j.WriteNumber("unit", unit);
                j.WriteStartArray("sent");
                foreach (string frame in sent)
                {
                    j.WriteStringValue(frame);
                }

                j.WriteEndArray();
                j.WriteStartArray("received");
                foreach (string frame in received)
                {
                    j.WriteStringValue(frame);
                }

                j.WriteEndArray();
                if (text is null)
                {
                    j.WriteNull("text");
                }
                else
                {
                    j.WriteString("text", text);
                }

                if (error is not null)
                {
                    j.WritePropertyName("error");
                    JsonSerializer.Serialize(j, error, CliJsonContext.Console.ErrorInfo);
                }

                j.WriteEndObject();
            });
}
