namespace OmronHostLink;

/// <summary>
/// A Host Link client as application code sees it: the unit the client addresses (<see cref="IHostLinkUnit"/>), the
/// way to the other units on the line (<see cref="IHostLinkUnit.Unit(int)"/>), and the link's lifetime.
/// <see cref="HostLinkClient"/> implements it; register and inject it to test application code with a test double.
/// </summary>
public interface IHostLinkClient : IHostLinkUnit, IAsyncDisposable, IDisposable
{
    /// <inheritdoc cref="HostLinkClient.Description"/>
    string Description { get; }
}
