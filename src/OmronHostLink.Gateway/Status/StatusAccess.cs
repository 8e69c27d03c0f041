using System.Net;
using System.Security.Cryptography;
using System.Text;
using Microsoft.AspNetCore.Http;
using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// The gate every request passes before the page: the browser's protections on every answer (no script, style or
/// frame from elsewhere, no sniffing, no referrer), the access token when one is set — <c>Authorization: Bearer</c>,
/// or the cookie a browser is given once it opened <c>/?token=…</c> — and otherwise only the names of this machine in
/// the <c>Host</c> header (a page elsewhere that points a name of its own at 127.0.0.1 reads nothing); then only
/// <c>GET</c> and <c>HEAD</c>: nothing the page serves changes anything.
/// </summary>
internal sealed class StatusAccess
{
    /// <summary>The cookie that carries access for a browser.</summary>
    public const string CookieName = "hostlink-status";

    /// <summary>The query parameter a browser opens the page with once.</summary>
    public const string TokenParameter = "token";

    private const string Policy = "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; connect-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";

    private readonly byte[]? _token;
    private readonly string? _cookie;
    private readonly ILogger _logger;

    /// <summary>A gate for <paramref name="options"/>: with its token, if it has one.</summary>
    public StatusAccess(StatusOptions options, ILogger logger)
    {
        ArgumentNullException.ThrowIfNull(options);
        _logger = logger;
        if (options.HasToken)
        {
            _token = SHA256.HashData(Encoding.UTF8.GetBytes(options.AccessToken!));
            // The cookie holds a value derived from the token, not the token itself.
            _cookie = Convert.ToHexString(HMACSHA256.HashData(Encoding.UTF8.GetBytes(options.AccessToken!), "OmronHostLink.Gateway status page"u8));
        }
    }

    /// <summary>Passes <paramref name="context"/> on to <paramref name="next"/> when it may, or answers it.</summary>
    public Task InvokeAsync(HttpContext context, RequestDelegate next)
    {
        ArgumentNullException.ThrowIfNull(context);
        ArgumentNullException.ThrowIfNull(next);
        HttpRequest request = context.Request;
        HttpResponse response = context.Response;
        response.Headers.ContentSecurityPolicy = Policy;
        response.Headers.XContentTypeOptions = "nosniff";
        response.Headers.XFrameOptions = "DENY";
        response.Headers["Referrer-Policy"] = "no-referrer";
        response.Headers["Cross-Origin-Resource-Policy"] = "same-origin";

        if (_token is null)
        {
            if (!IsThisMachine(request.Host))
            {
                return Refuse(context, StatusCodes.Status400BadRequest, $"this page answers to its address or localhost, not to '{request.Host.Host}'", "This status page answers to its IP address or localhost. Set Status:AccessToken to open it under another name.");
            }
        }
        else if (request.Query.TryGetValue(TokenParameter, out var offered))
        {
            if (!Matches(_token, offered.ToString()))
            {
                return Unauthorized(context, "a wrong token in the address");
            }

            // Keep access in a cookie and take the token out of the address bar and the history.
            response.Cookies.Append(CookieName, _cookie!, new CookieOptions { HttpOnly = true, SameSite = SameSiteMode.Strict, Path = "/", IsEssential = true });
            response.Headers.CacheControl = "no-store";
            response.Redirect(request.PathBase + request.Path, permanent: false);
            response.StatusCode = StatusCodes.Status303SeeOther;
            return Task.CompletedTask;
        }
        else if (!Bearer(request) && !CookieMatches(request))
        {
            return Unauthorized(context, request.Headers.Authorization.Count > 0 || request.Cookies.ContainsKey(CookieName) ? "a wrong token" : "no token");
        }

        if (!HttpMethods.IsGet(request.Method) && !HttpMethods.IsHead(request.Method))
        {
            response.Headers.Allow = "GET, HEAD";
            return Refuse(context, StatusCodes.Status405MethodNotAllowed, $"{request.Method} is not served", "This status page is read-only: it answers GET and HEAD only.");
        }

        return next(context);
    }

    private static bool IsThisMachine(HostString host)
        => host.HasValue && (string.Equals(host.Host, "localhost", StringComparison.OrdinalIgnoreCase) || IPAddress.TryParse(host.Host, out _));

    private static bool Matches(byte[] expected, string offered)
        => CryptographicOperations.FixedTimeEquals(expected, SHA256.HashData(Encoding.UTF8.GetBytes(offered)));

    private bool Bearer(HttpRequest request)
    {
        string header = request.Headers.Authorization.ToString();
        return header.StartsWith("Bearer ", StringComparison.OrdinalIgnoreCase) && Matches(_token!, header["Bearer ".Length..].Trim());
    }

    private bool CookieMatches(HttpRequest request)
        => request.Cookies.TryGetValue(CookieName, out string? value) && value is not null
            && CryptographicOperations.FixedTimeEquals(Encoding.ASCII.GetBytes(_cookie!), Encoding.ASCII.GetBytes(value));

    private Task Unauthorized(HttpContext context, string why)
    {
        context.Response.Headers.WWWAuthenticate = "Bearer realm=\"OmronHostLink.Gateway status page\"";
        return Refuse(context, StatusCodes.Status401Unauthorized, why, "This status page needs its access token: open /?token=YOUR-TOKEN once (the browser then keeps it), or send Authorization: Bearer YOUR-TOKEN.");
    }

    private Task Refuse(HttpContext context, int status, string why, string text)
    {
        StatusLog.Refused(_logger, context.Request.Method, context.Request.Path.ToString(), context.Connection.RemoteIpAddress?.ToString() ?? "?", why);
        context.Response.StatusCode = status;
        context.Response.Headers.CacheControl = "no-store";
        context.Response.ContentType = "text/plain; charset=utf-8";
        return HttpMethods.IsHead(context.Request.Method) ? Task.CompletedTask : context.Response.WriteAsync(text + "\n");
    }
}
