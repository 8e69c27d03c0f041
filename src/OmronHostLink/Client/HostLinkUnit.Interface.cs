namespace OmronHostLink;

/// <summary>The unit as <see cref="IHostLinkUnit"/>: views come back as the interface.</summary>
public partial class HostLinkUnit : IHostLinkUnit
{
    /// <inheritdoc/>
    IHostLinkUnit IHostLinkUnit.Unit(int unitNumber) => Unit(unitNumber);

    /// <inheritdoc/>
    IHostLinkUnit IHostLinkUnit.Unit(int unitNumber, HostLinkCommandSet commandSet) => Unit(unitNumber, commandSet);

    /// <inheritdoc/>
    IHostLinkUnit IHostLinkUnit.WithWordOrder(WordOrder order) => WithWordOrder(order);
}
