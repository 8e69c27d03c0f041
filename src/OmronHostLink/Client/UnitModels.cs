using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Logging.Abstractions;

namespace OmronHostLink;

/// <summary>
/// The PLC model each unit of one client is checked against: the configured one for every unit, or — with
/// <c>Model = "auto"</c> — the one each unit names when asked MM, once per unit on first use. Shared by the client and
/// all its unit views.
/// </summary>
internal sealed class UnitModels
{
    private readonly PlcModelProfile? _configured;
    private readonly bool _detect;
    private readonly Task<PlcModelProfile?>?[] _detected = new Task<PlcModelProfile?>?[32];

    // Without a configured model, what each unit named to MM for the QQ decision alone (addresses stay unchecked).
    private readonly Task<PlcModelProfile?>?[] _named = new Task<PlcModelProfile?>?[32];
    private readonly object _gate = new();
    private readonly ILogger _logger;

    public UnitModels(string? model, ILoggerFactory? loggerFactory = null)
    {
        _logger = loggerFactory?.CreateLogger("OmronHostLink") ?? NullLogger.Instance;
        if (SettingRules.IsAutoModel(model))
        {
            _detect = true;
        }
        else if (!string.IsNullOrWhiteSpace(model))
        {
            _configured = PlcModelProfile.Parse(model!);
        }
    }

    /// <summary>The client's log (model detection, QQ refused).</summary>
    public ILogger Logger => _logger;

    /// <summary>No model is configured and none is detected: only the CS/CJ sizes are checked.</summary>
    public bool Off => _configured is null && !_detect;

    /// <summary>The profile of <paramref name="unit"/> when it is known without asking the PLC (again).</summary>
    public bool TryGet(int unit, out PlcModelProfile? profile)
    {
        if (!_detect)
        {
            profile = _configured;
            return true;
        }

        var task = Volatile.Read(ref _detected[unit]);
        if (task is { Status: TaskStatus.RanToCompletion })
        {
            profile = task.Result;
            return true;
        }

        profile = null;
        return false;
    }

    /// <summary>
    /// The profile of <paramref name="unit"/>, asking it MM the first time. An MM that fails with a timeout or a broken
    /// link is not remembered (the next use asks again); a PLC that refuses MM or names a code no profile has is
    /// remembered as having no profile.
    /// </summary>
    public Task<PlcModelProfile?> GetAsync(int unit, Func<CancellationToken, ValueTask<PlcModel>> readModel, CancellationToken cancellationToken)
    {
        if (TryGet(unit, out var known))
        {
            return Task.FromResult(known);
        }

        lock (_gate)
        {
            var task = _detected[unit];
            if (task is null || task.IsFaulted || task.IsCanceled)
            {
                task = DetectAsync(unit, readModel, cancellationToken);
                _detected[unit] = task;
            }

            return task;
        }
    }

    /// <summary>
    /// The profile that decides whether <paramref name="unit"/> is read with QQ (<see cref="CompoundReadMode.Auto"/>):
    /// the one <see cref="GetAsync"/> gives where a model is configured or detected; otherwise what the unit names when
    /// asked MM, once (not remembered after a timeout), used for that decision alone.
    /// </summary>
    public Task<PlcModelProfile?> GetForCompoundAsync(int unit, Func<CancellationToken, ValueTask<PlcModel>> readModel, CancellationToken cancellationToken)
    {
        if (!Off)
        {
            return GetAsync(unit, readModel, cancellationToken);
        }

        lock (_gate)
        {
            var task = _named[unit];
            if (task is null || task.IsFaulted || task.IsCanceled)
            {
                task = DetectAsync(unit, readModel, cancellationToken, forCompoundRead: true);
                _named[unit] = task;
            }

            return task;
        }
    }

    /// <summary>The profile <see cref="GetForCompoundAsync"/> gives when it is known without asking the PLC (again).</summary>
    public bool TryGetForCompound(int unit, out PlcModelProfile? profile)
    {
        if (!Off)
        {
            return TryGet(unit, out profile);
        }

        var task = Volatile.Read(ref _named[unit]);
        profile = task is { Status: TaskStatus.RanToCompletion } ? task.Result : null;
        return task is { Status: TaskStatus.RanToCompletion };
    }

    private async Task<PlcModelProfile?> DetectAsync(int unit, Func<CancellationToken, ValueTask<PlcModel>> readModel, CancellationToken cancellationToken, bool forCompoundRead = false)
    {
        PlcModel model;
        try
        {
            model = await readModel(cancellationToken).ConfigureAwait(false);
        }
        catch (HostLinkEndCodeException e)
        {
            // IC (no MM on this model) or another refusal: checked as without a model.
            Unknown(unit, $"MM was refused ({e.Message})", forCompoundRead);
            return null;
        }

        var profile = PlcModelProfile.FromModelCode(model.Code);
        string code = model.Code.ToString("X2", System.Globalization.CultureInfo.InvariantCulture);
        if (profile is null)
        {
            Unknown(unit, $"MM answered {model}, which no model profile has", forCompoundRead);
        }
        else if (forCompoundRead)
        {
            ModelLog.NamedForCompoundRead(_logger, unit, code, profile.DisplayName, profile.SupportsCompoundRead ? "QQ (the compound read)" : "area reads: the model has no QQ");
        }
        else
        {
            ModelLog.Detected(_logger, unit, code, profile.DisplayName);
        }

        return profile;
    }

    private void Unknown(int unit, string reason, bool forCompoundRead)
    {
        if (forCompoundRead)
        {
            ModelLog.UnknownForCompoundRead(_logger, unit, reason);
        }
        else
        {
            ModelLog.Unknown(_logger, unit, reason);
        }
    }
}
