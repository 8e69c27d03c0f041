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
