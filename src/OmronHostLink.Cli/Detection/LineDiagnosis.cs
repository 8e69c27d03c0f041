using System.Globalization;

namespace OmronHostLink.Cli.Detection;

/// <summary>What a search's tries say about the line, in plain words: what was found, or why nothing answered.</summary>
internal static class LineDiagnosis
{
    /// <summary>The sentences for <paramref name="outcome"/>; <paramref name="given"/> is the setting tried first (the one the user has), <paramref name="units"/> the units the TS went to.</summary>
    public static List<string> Describe(LineDetector.Outcome outcome, (int Baud, LineFormat Format) given, IReadOnlyList<int> units, bool settingsFixed)
    {
        var said = new List<string>();
        ProbeTry? found = outcome.Found;
        if (found is not null)
        {
            if (!settingsFixed && (found.Baud != given.Baud || !found.Format.SameOnTheWire(given.Format)))
            {
                said.Add($"The settings given, {given.Baud} {given.Format}{(given == (9600, LineFormat.OmronDefault) ? " (Omron's default)" : "")}, get no answer: the PLC's port runs at {found.Baud} {found.Format}. {Differences(given, (found.Baud, found.Format))}");
            }

            if (!settingsFixed)
            {
                said.Add($"1 and 2 stop bits cannot be told apart on the line (a receiver checks only the first), so {found.Format} and {found.Format.OtherStopBits} work alike; set the one the PLC's port is set to if you know it.");
            }

            if (outcome.Echo == true)
            {
                said.Add("Our own frames come back before each answer: the adapter is a 2-wire RS-485 one without echo suppression. Set LocalEcho (--local-echo), as below, or turn echo off in the adapter.");
            }

            if (found.Reply.EndCode is { } code)
            {
                said.Add(code == "13"
                    ? $"Unit {found.Unit:D2} answered TS with end code 13 (FCS error): it heard our frame with a character changed. The settings are right; the line damages characters: look at noise, grounding, shielding and termination."
                    : $"Unit {found.Unit:D2} answered TS with end code {code} ({EndCodeMeaning(code)}). The settings are right.");
            }

            if (found.Reply.Ic)
            {
                said.Add($"Unit {found.Unit:D2} answered IC: its port takes our frames but not TS (an old model, or a port set to another protocol answering in Host Link framing). The settings are right.");
            }

            if (found.Reply.BadFcs > 0 || found.Reply.Unframed > 0)
            {
                said.Add($"Besides the answer, {Count(found.Reply.BadFcs, "frame")} with a wrong FCS and {Count(found.Reply.Unframed, "byte")} that do not frame came back: the line is noisy.");
            }

            return said;
        }

        List<ProbeTry> tries = outcome.Tries.ToList();
        string unitsTried = units.Count == 1 ? $"unit {units[0]:D2}" : $"units {string.Join(", ", units.Select(u => u.ToString("D2", CultureInfo.InvariantCulture)))}";
        string checks = $"Check the port and the cable (TX and RX crossed on RS-232; A and B, and termination, on RS-485), the adapter and its driver, that the PLC is on, that its port is set to Host Link (not peripheral bus, NT Link or serial gateway), and its unit number: the TS went to {unitsTried} only; --search-units 0-31 tries every unit number at every setting (slower).";
        if (tries.All(t => t.Reply.Silent))
        {
            said.Add($"Silence: no byte came back at any of the {Count(tries.Count, "setting")} tried ({Settings(tries)}). {checks}");
            if (settingsFixed)
            {
                said.Add("Over a serial-device server the speed and format are the server's serial port settings, set in its own configuration: they must match the PLC's port.");
            }

            return said;
        }

        if (outcome.Echo == true)
        {
            bool onlyEcho = tries.All(t => t.Reply.Copies == 1 && t.Reply.Unframed == 0 && t.Reply.BadFcs == 0 && t.Reply.OtherFrames == 0);
            said.Add($"Our own frames came back at every setting{(onlyEcho ? ", and nothing else" : "")}: the adapter echoes what it sends (a 2-wire RS-485 adapter without echo suppression: set LocalEcho, --local-echo) and no PLC answered behind the echo. {checks}");
        }

        List<ProbeTry> garbled = tries.Where(t => t.Reply.Unframed > 0).ToList();
        if (garbled.Count > 0)
        {
            ProbeTry sample = garbled[0];
            said.Add($"Bytes that do not frame came back at {Settings(garbled)} (at {sample.Settings}: \"{sample.Reply.Sample()}\"): something on the line sends at a speed or format other than the one tried — a PLC port set to other settings or another protocol, another master polling the line — or the line is noisy.");
        }

        List<ProbeTry> badFcs = tries.Where(t => t.Reply.BadFcs > 0).ToList();
        if (badFcs.Count > 0)
        {
            said.Add($"Frames with a wrong FCS came back at {Settings(badFcs)}: the speed and format are likely right but the line damages characters: noise, grounding, a missing termination, a cable too long for the speed.");
        }

        List<ProbeTry> other = tries.Where(t => t.Reply.OtherFrames > 0).ToList();
        if (other.Count > 0)
        {
            said.Add($"Sound frames that are not answers to our TS came back at {Settings(other)}: another unit or another master is talking on the line at those settings.");
        }

        if (said.Count == 0)
        {
            said.Add($"Nothing answered at any of the {Count(tries.Count, "setting")} tried. {checks}");
        }

        return said;
    }

    /// <summary>How two settings differ, in words.</summary>
    internal static string Differences((int Baud, LineFormat Format) given, (int Baud, LineFormat Format) found)
    {
        var parts = new List<string>();
        if (given.Baud != found.Baud)
        {
            parts.Add($"the speed differs ({found.Baud} bps, not {given.Baud})");
        }

        if (given.Format.DataBits != found.Format.DataBits || given.Format.Parity != found.Format.Parity)
        {
            parts.Add($"the format differs ({found.Format.DataBits} data bits and {ParityWords(found.Format)}, not {given.Format.DataBits} and {ParityWords(given.Format)})");
        }

        return parts.Count == 0 ? string.Empty : char.ToUpperInvariant(parts[0][0]) + string.Join(", and ", parts)[1..] + ".";
    }

    private static string ParityWords(LineFormat format) => format.Parity switch
    {
        Transports.SerialParity.Even => "even parity",
        Transports.SerialParity.Odd => "odd parity",
        _ => "no parity",
    };

    private static string EndCodeMeaning(string code)
        => EndCodes.TryParse(System.Text.Encoding.ASCII.GetBytes(code), out EndCode parsed) ? parsed.Meaning() : "not an end code the manuals define";

    private static string Settings(IEnumerable<ProbeTry> tries)
    {
        string[] distinct = tries.Select(t => t.Settings).Distinct().ToArray();
        return distinct.Length <= 6 ? string.Join(", ", distinct) : string.Join(", ", distinct.Take(5)) + $" and {distinct.Length - 5} more";
    }

    private static string Count(int n, string what) => n == 1 ? $"1 {what}" : $"{n} {what}s";
}
