namespace OmronHostLink.Link;

/// <summary>
/// The gap the line keeps between exchanges: the next command waits until the time since the last exchange ended
/// (whatever it was, answered or not) is the longer of the link's send interval and the unit's.
/// </summary>
internal sealed class SendSpacing
{
    private readonly HostLinkConnectionOptions _options;
    private readonly TimeProvider _time;
    private long _lastExchangeEnded;

    public SendSpacing(HostLinkConnectionOptions options)
    {
        _options = options;
        _time = options.TimeProvider;
    }

    /// <summary>Marks the end of an exchange, from which the next gap is counted.</summary>
    public void ExchangeEnded() => _lastExchangeEnded = _time.GetTimestamp();

    /// <summary>Waits out what is left of the gap before a command to <paramref name="unit"/>.</summary>
    public Task WaitAsync(int unit, CancellationToken cancellationToken)
    {
        TimeSpan gap = _options.SendIntervalFor(unit);
        if (gap <= TimeSpan.Zero || _lastExchangeEnded == 0)
        {
            return Task.CompletedTask;
        }

        TimeSpan remaining = gap - _time.GetElapsedTime(_lastExchangeEnded);
        if (remaining <= TimeSpan.Zero)
        {
            return Task.CompletedTask;
        }

#if NET
        return Task.Delay(remaining, _time, cancellationToken);
#else
        return _time.Delay(remaining, cancellationToken);
#endif
    }
}
