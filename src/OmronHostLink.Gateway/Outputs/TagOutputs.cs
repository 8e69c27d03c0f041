namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// The configured outputs as one: the polling engine reports to this, and it passes every report to each output in
/// registration order. The pipeline knows no output by name.
/// </summary>
/// <param name="outputs">The outputs (<see cref="OpenLinks"/>, MQTT, …).</param>
internal sealed class TagOutputs(IEnumerable<ITagOutput> outputs) : ITagOutput, IScanOutput
{
    private readonly ITagOutput[] _outputs = outputs.ToArray();

    /// <summary>How many outputs there are.</summary>
    public int Count => _outputs.Length;

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client)
    {
        foreach (ITagOutput output in _outputs)
        {
            output.LinkOpened(link, client);
        }
    }

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
        foreach (ITagOutput output in _outputs)
        {
            output.LinkChanged(link, state, detail);
        }
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
        foreach (ITagOutput output in _outputs)
        {
            output.TagChanged(change);
        }
    }

    /// <inheritdoc/>
    public void UnitChanged(string link, int unit, UnitState state, string? detail = null)
    {
        foreach (ITagOutput output in _outputs)
        {
            output.UnitChanged(link, unit, state, detail);
        }
    }

    /// <inheritdoc/>
    public void ScanPlanned(ScanPlan plan)
    {
        foreach (IScanOutput output in _outputs.OfType<IScanOutput>())
        {
            output.ScanPlanned(plan);
        }
    }

    /// <inheritdoc/>
    public void ScanCycled(ScanCycle cycle)
    {
        foreach (IScanOutput output in _outputs.OfType<IScanOutput>())
        {
            output.ScanCycled(cycle);
        }
    }
}
