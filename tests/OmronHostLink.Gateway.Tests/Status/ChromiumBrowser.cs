using OpenQA.Selenium;
using OpenQA.Selenium.Chrome;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// Debian's headless Chromium (packages <c>chromium</c> and <c>chromium-driver</c>) driven over WebDriver by Selenium:
/// no sandbox, no GPU, nothing fetched in the background, a fresh profile of its own, deleted afterwards. Without the
/// packages the tests fail and say which to install.
/// </summary>
internal sealed class ChromiumBrowser : IDisposable
{
    private const string Driver = "/usr/bin/chromedriver";
    private const string Browser = "/usr/bin/chromium";

    private readonly string _profile;

    private ChromiumBrowser(ChromeDriver driver, string profile)
    {
        Session = driver;
        _profile = profile;
    }

    /// <summary>The WebDriver session.</summary>
    public ChromeDriver Session { get; }

    /// <summary>Starts a browser whose window is <paramref name="width"/> × <paramref name="height"/> CSS pixels.</summary>
    public static ChromiumBrowser Start(int width = 1280, int height = 900)
    {
        if (!File.Exists(Driver) || !File.Exists(Browser))
        {
            throw new InvalidOperationException($"Headless Chromium is needed: {Browser} and {Driver} (apt-get install chromium chromium-driver).");
        }

        string profile = Directory.CreateTempSubdirectory("ohl-chromium-").FullName;
        ChromeDriverService service = ChromeDriverService.CreateDefaultService(Path.GetDirectoryName(Driver)!, Path.GetFileName(Driver));
        service.SuppressInitialDiagnosticInformation = true;
        service.HideCommandPromptWindow = true;
        var options = new ChromeOptions { BinaryLocation = Browser };
        options.AddArguments(
            "--headless=new",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--disable-dev-shm-usage",
            $"--user-data-dir={profile}",
            $"--window-size={width},{height}");
        try
        {
            // A loaded machine may take long to start a browser.
            var driver = new ChromeDriver(service, options, TimeSpan.FromMinutes(2));
            driver.Manage().Timeouts().PageLoad = TimeSpan.FromMinutes(1);
            driver.Manage().Timeouts().AsynchronousJavaScript = TimeSpan.FromMinutes(1);
            return new ChromiumBrowser(driver, profile);
        }
        catch
        {
            service.Dispose();
            Directory.Delete(profile, recursive: true);
            throw;
        }
    }

    /// <summary>Runs <paramref name="script"/> in the page and returns its result.</summary>
    public object? Script(string script, params object[] args) => Session.ExecuteScript(script, args);

    /// <summary>Saves a screenshot of the window as <paramref name="path"/> (PNG).</summary>
    public void Screenshot(string path)
    {
        Directory.CreateDirectory(Path.GetDirectoryName(path)!);
        Session.GetScreenshot().SaveAsFile(path);
    }

    /// <summary>Waits until <paramref name="condition"/> holds in the page, at most <paramref name="patience"/> (default 60 s).</summary>
    public async Task<T> Until<T>(Func<ChromiumBrowser, T?> condition, string what, TimeSpan? patience = null)
    {
        TimeSpan limit = patience ?? TimeSpan.FromSeconds(60);
        Exception? last = null;
        T? found = default;
        bool Holds()
        {
            try
            {
                T? value = condition(this);
                found = value;
                return value is not null && !(value is bool b && !b);
            }
            catch (WebDriverException e)
            {
                // The page re-rendered the element meanwhile (stale): look again.
                last = e;
                return false;
            }
        }

        await Eventually.UntilAsync(Holds, what, () => $"{(last is null ? "" : "Last: " + last.Message + Environment.NewLine)}Page: {Text()}", limit);
        return found!;
    }

    /// <summary>The text of the page's visible view.</summary>
    public string Text()
    {
        try
        {
            return Session.FindElement(By.TagName("main")).Text;
        }
        catch (WebDriverException e)
        {
            return e.Message;
        }
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        Session.Quit();
        Session.Dispose();
        try
        {
            Directory.Delete(_profile, recursive: true);
        }
        catch (IOException)
        {
        }
    }
}
