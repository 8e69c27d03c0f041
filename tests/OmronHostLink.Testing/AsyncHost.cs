using Microsoft.Extensions.Hosting;

namespace OmronHostLink.Testing;

/// <summary>A started host for <c>await using</c> or a test's clean-up list: stopped, then disposed.</summary>
public sealed class AsyncHost(IHost host) : IAsyncDisposable
{
    /// <inheritdoc/>
    public async ValueTask DisposeAsync()
    {
        await host.StopAsync().ConfigureAwait(false);
        host.Dispose();
    }
}
