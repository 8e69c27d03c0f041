using OmronHostLink.Link;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>QQ, C-mode's compound read: scattered bits and words registered once (QQMR), then read with one short command (QQIR).</summary>
public partial class HostLinkUnit
{
    /// <summary>
    /// Reads scattered bits and words in one exchange with QQ, C-mode's compound read, so the values are one snapshot:
    /// a word address gives its value, a bit address 0 or 1, a timer or counter its PV. The addresses are registered
    /// with the PLC (QQMR) the first time and whenever the unit holds another registration (a PLC holds one per unit);
    /// later calls with the same addresses send only the read (QQIR). A PLC that lost the registration (restarted:
    /// end code 19) is registered again and read again, once. At most 128 addresses (a timer/counter counts as two);
    /// C-mode whatever this view's command set. PLCs without QQ (the CP2E, for one) answer IC.
    /// </summary>
    /// <param name="addresses">The addresses, in the order of the values returned.</param>
    /// <param name="cancellationToken">Cancels the exchange.</param>
    /// <returns>One value per address.</returns>
    /// <exception cref="FormatException">An address is not valid (nothing is sent).</exception>
    /// <exception cref="ArgumentException">No addresses, more than 128, or one QQ cannot reach (nothing is sent).</exception>
    public async Task<ushort[]> ReadCompoundAsync(IReadOnlyList<string> addresses, CancellationToken cancellationToken = default)
    {
        Guard.NotNull(addresses);
        var items = new CompoundItem[addresses.Count];
        var parsed = new PlcAddress[addresses.Count];
        for (int i = 0; i < items.Length; i++)
        {
            PlcAddress address = PlcAddress.Parse(addresses[i] ?? throw new ArgumentException($"Address {i} is null.", nameof(addresses)));
            address.EnsureRange(1, HostLinkCommandSet.CMode, forWrite: false);
            items[i] = CompoundItem.For(address);
            parsed[i] = address;
        }

        if (await GetModelProfileAsync(cancellationToken).ConfigureAwait(false) is { } model)
        {
            model.EnsureCMode("QQ", "compound read");
            foreach (PlcAddress address in parsed)
            {
                model.EnsureRange(address.AsWord(), 1, forWrite: false);
            }
        }

        _ = new CompoundRegisterCommand(items); // refuses an empty or oversized set before anything is sent
        ushort[] values = await ReadCompoundItemsAsync(items, cancellationToken).ConfigureAwait(false);
        for (int i = 0; i < values.Length; i++)
        {
            if (parsed[i].IsBit && !items[i].IsBit)
            {
                // A bit of DM or EM: QQ reads its word.
                values[i] = PlcWords.GetBit(values[i], parsed[i].Bit) ? (ushort)1 : (ushort)0;
            }
        }

        return values;
    }

    /// <summary>Whether this unit holds <paramref name="items"/> as its registration, as far as this client knows.</summary>
    private protected bool HoldsCompound(IReadOnlyList<CompoundItem> items) => CompoundReads.Holds(UnitNumber, items, Connection.Openings);

    /// <summary>QQIR of <paramref name="items"/>, registering them first unless the unit holds them; once more after end code 19.</summary>
    private protected async ValueTask<ushort[]> ReadCompoundItemsAsync(IReadOnlyList<CompoundItem> items, CancellationToken cancellationToken)
    {
        // A model known to have no QQ is not sent one (it would answer IC).
        (await GetModelProfileAsync(cancellationToken).ConfigureAwait(false))?.EnsureCMode("QQ", "compound read");
        await CompoundReads.Gate(UnitNumber).WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            bool registeredNow = false;
            if (!HoldsCompound(items))
            {
                await RegisterCompoundAsync(items, cancellationToken).ConfigureAwait(false);
                registeredNow = true;
            }

            try
            {
                return await CompoundReadAsync(items, cancellationToken).ConfigureAwait(false);
            }
            catch (HostLinkEndCodeException e) when (e.EndCode == EndCode.NotExecutable && !registeredNow)
            {
                // The PLC lost the registration (it restarted): register again and read again, once.
                CompoundReads.Forget(UnitNumber);
                await RegisterCompoundAsync(items, cancellationToken).ConfigureAwait(false);
                return await CompoundReadAsync(items, cancellationToken).ConfigureAwait(false);
            }
        }
        finally
        {
            CompoundReads.Gate(UnitNumber).Release();
        }
    }

    private async ValueTask RegisterCompoundAsync(IReadOnlyList<CompoundItem> items, CancellationToken cancellationToken)
    {
        var command = new CompoundRegisterCommand(items);
        CompoundReads.Forget(UnitNumber);
        await Connection.ExecuteAsync(
            Request(command),
            RetriesFor(command.Effect),
            static (text, s) =>
            {
                ReadOnlySpan<byte> data = CompoundAnswer(text, CompoundCommands.Register, s);
                return ExpectEmpty(data, "QQMR");
            },
            UnitNumber,
            cancellationToken).ConfigureAwait(false);
        CompoundReads.Registered(UnitNumber, items, Connection.Openings);
    }

    private ValueTask<ushort[]> CompoundReadAsync(IReadOnlyList<CompoundItem> items, CancellationToken cancellationToken)
    {
        CModeCommand command = CompoundCommands.ReadCommand;
        var shape = ExchangeShape.CMode(
            CModeCommand.PrefixLength + command.TextLength,
            atomLength: 1,
            multiFrameCommand: false,
            expectsAnswer: true,
            CompoundCommands.AnswerFixed + CompoundCommands.DataLength(items),
            answerCanEqualCommand: false);
        return Connection.ExecuteAsync(
            new HostLinkRequest(UnitNumber, command.Header, command.ToMessage(UnitNumber), shape) { ReadOnly = command.Effect == CommandEffect.ReadOnly },
            RetriesFor(command.Effect),
            static (text, s) =>
            {
                ReadOnlySpan<byte> data = CompoundAnswer(text, CompoundCommands.Read, s.unit);
                var values = new ushort[s.items.Count];
                CompoundCommands.ReadData(data, s.items, values);
                return values;
            },
            (items, unit: UnitNumber),
            cancellationToken);
    }

    /// <summary>The data of a QQ answer: its sub-header checked, an end code other than 00 raised.</summary>
    private static ReadOnlySpan<byte> CompoundAnswer(ReadOnlySpan<byte> text, string subHeader, int unit)
    {
        if (text.Length < 2 || text[0] != (byte)subHeader[0] || text[1] != (byte)subHeader[1])
        {
            throw new HostLinkFrameException(FrameError.WrongHeader, $"The answer to QQ{subHeader} does not echo its sub-header {subHeader}.", text);
        }

        return CModeResponse.GetData(text.Slice(2), "QQ" + subHeader, unit);
    }
}
