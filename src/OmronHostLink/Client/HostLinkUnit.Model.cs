using OmronHostLink.Planning;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>The PLC model a unit is checked against (<see cref="HostLinkClientOptions.Model"/>).</summary>
public partial class HostLinkUnit
{
    /// <summary>
    /// The model profile this unit's addresses and commands are checked against: the configured
    /// <see cref="HostLinkClientOptions.Model"/>; with <c>"auto"</c>, the profile of the code the unit answers to MM
    /// (asked once, on first use; where one code covers several models, only what all of them have); null when no
    /// model is configured or the PLC named none the library knows.
    /// </summary>
    /// <param name="cancellationToken">Cancels the MM exchange.</param>
    /// <returns>The profile, or null.</returns>
    /// <exception cref="HostLinkTimeoutException">The unit did not answer MM (asked again on the next use).</exception>
    public Task<PlcModelProfile?> GetModelProfileAsync(CancellationToken cancellationToken = default)
        => Models.TryGet(UnitNumber, out PlcModelProfile? known)
            ? Task.FromResult(known)
            : Models.GetAsync(UnitNumber, ct => new ValueTask<PlcModel>(ReadModelAsync(ct)), cancellationToken);

    /// <summary>
    /// Refuses, before anything is sent, a C-mode command the unit's model (configured, or already detected) does not
    /// list: MM and XZ on a CP2E, for example. TS is answered by every model.
    /// </summary>
    private void EnsureModelAccepts(CModeCommand command)
    {
        if (command.Row != CModeCommands.Test && Models.TryGet(UnitNumber, out PlcModelProfile? model) && model is not null)
        {
            model.EnsureCMode(command.Header, command.Row.Name);
        }
    }

    /// <summary>
    /// Refuses a whole plan before its first read is sent when one of its reads is something a unit's model lacks (the
    /// unit's MM is asked first where the model is detected).
    /// </summary>
    private async ValueTask EnsurePlanAsync(ReadPlan plan, CancellationToken cancellationToken)
    {
        if (Models.Off)
        {
            return;
        }

        foreach (PlannedRead read in plan.Reads)
        {
            HostLinkUnit unit = read.Unit == UnitNumber ? this : Unit(read.Unit);
            EnsureModel(await unit.GetModelProfileAsync(cancellationToken).ConfigureAwait(false), read);
        }
    }

    private async Task<ushort[]> ReadWordsOfDetectedModelAsync(PlcAddress address, int count, CancellationToken cancellationToken)
    {
        PlcModelProfile? model = await GetModelProfileAsync(cancellationToken).ConfigureAwait(false);
        Commands.EnsureModel(model, address, count, forWrite: false);
        return await Commands.ReadWordsAsync(this, address, count, model, cancellationToken).ConfigureAwait(false);
    }

    private async Task WriteWordsOfDetectedModelAsync(PlcAddress address, ReadOnlyMemory<ushort> words, CancellationToken cancellationToken)
    {
        PlcModelProfile? model = await GetModelProfileAsync(cancellationToken).ConfigureAwait(false);
        Commands.EnsureModel(model, address, words.Length, forWrite: true);
        await Commands.WriteWordsAsync(this, address, words, model, cancellationToken).ConfigureAwait(false);
    }
}
