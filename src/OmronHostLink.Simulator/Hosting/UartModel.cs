using OmronHostLink.Transports;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// What a UART receives from a transmitter set to other line settings, bit by bit: the transmitter's characters become a
/// waveform (idle high, a start bit, the data bits least significant first, the parity bit, the stop bits, back to back)
/// at its speed, and the receiver, at its own speed and format, waits for a falling edge, samples each bit in the middle
/// of where it expects it, checks the parity bit and the first stop bit only (as standard UARTs do: one or two stop bits
/// on the other side make no difference), and hunts for the next falling edge after the stop bit. Matching settings give
/// the bytes back unchanged; other speeds give garbage, other formats parity and framing errors or changed characters.
/// </summary>
internal static class UartModel
{
    /// <summary>One character as the receiver took it.</summary>
    /// <param name="Value">The data bits, least significant first (bit 7 zero with 7 data bits).</param>
    /// <param name="ParityError">The parity bit did not match the receiver's parity.</param>
    /// <param name="FramingError">The stop bit was low.</param>
    public readonly record struct Received(byte Value, bool ParityError, bool FramingError)
    {
        /// <summary>Whether the receiver flagged the character.</summary>
        public bool Error => ParityError || FramingError;
    }

    /// <summary>The characters a receiver set to <paramref name="receiver"/> takes from <paramref name="bytes"/> sent back to back at <paramref name="transmitter"/>'s settings after an idle line.</summary>
    public static List<Received> Transfer(ReadOnlySpan<byte> bytes, SerialLineSettings transmitter, SerialLineSettings receiver)
    {
        bool[] wave = Waveform(bytes, transmitter);
        double txBit = 1.0 / transmitter.BaudRate;
        double rxBit = 1.0 / receiver.BaudRate;
        int frameBits = 1 + receiver.DataBits + (receiver.Parity == SerialParity.None ? 0 : 1) + 1;
        var received = new List<Received>();
        double ready = 0;
        while (true)
        {
            double? edge = NextFallingEdge(wave, txBit, ready);
            if (edge is null)
            {
                return received;
            }

            double Sample(int bit) => edge.Value + ((bit + 0.5) * rxBit);
            if (Level(wave, txBit, Sample(0)))
            {
                // A glitch, not a start bit: hunt again after the sample.
                ready = Sample(0);
                continue;
            }

            int value = 0;
            int ones = 0;
            for (int i = 0; i < receiver.DataBits; i++)
            {
                if (Level(wave, txBit, Sample(1 + i)))
                {
                    value |= 1 << i;
                    ones++;
                }
            }

            bool parityError = false;
            int next = 1 + receiver.DataBits;
            if (receiver.Parity != SerialParity.None)
            {
                bool parityBit = Level(wave, txBit, Sample(next));
                bool expected = receiver.Parity == SerialParity.Even ? ones % 2 == 1 : ones % 2 == 0;
                parityError = parityBit != expected;
                next++;
            }

            bool framingError = !Level(wave, txBit, Sample(next));
            received.Add(new Received((byte)value, parityError, framingError));
            ready = Sample(frameBits - 1);
        }
    }

    /// <summary>The transmitted bits, one per bit time from the first start bit; the line is high before and after.</summary>
    private static bool[] Waveform(ReadOnlySpan<byte> bytes, SerialLineSettings transmitter)
    {
        int perChar = transmitter.BitsPerCharacter;
        var wave = new bool[bytes.Length * perChar];
        int at = 0;
        foreach (byte b in bytes)
        {
            wave[at++] = false;
            int ones = 0;
            for (int i = 0; i < transmitter.DataBits; i++)
            {
                bool bit = ((b >> i) & 1) != 0;
                wave[at++] = bit;
                ones += bit ? 1 : 0;
            }

            if (transmitter.Parity != SerialParity.None)
            {
                wave[at++] = transmitter.Parity == SerialParity.Even ? ones % 2 == 1 : ones % 2 == 0;
            }

            for (int i = 0; i < (int)transmitter.StopBits; i++)
            {
                wave[at++] = true;
            }
        }

        return wave;
    }

    private static bool Level(bool[] wave, double bitTime, double time)
    {
        if (time < 0)
        {
            return true;
        }

        long index = (long)Math.Floor(time / bitTime);
        return index >= wave.Length || wave[index];
    }

    /// <summary>The first time at or after <paramref name="from"/> when the line goes from high to low.</summary>
    private static double? NextFallingEdge(bool[] wave, double bitTime, double from)
    {
        long first = Math.Max(0, (long)Math.Ceiling((from / bitTime) - 1e-9));
        for (long i = first; i < wave.Length; i++)
        {
            bool before = i == 0 || wave[i - 1];
            if (before && !wave[i])
            {
                return i * bitTime;
            }
        }

        return null;
    }
}
