using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// One kind of link a client can use (a local serial port, a TCP serial-device server): its configuration keys, its
/// checks and the transport it opens. A client uses exactly one; <see cref="HostLinkClientSettings"/> lists them all.
/// </summary>
/// <remarks>A new kind of link is a new subclass here and one entry in <see cref="HostLinkClientSettings"/>'s list.</remarks>
public abstract class HostLinkEndpointSettings
{
    private protected HostLinkEndpointSettings()
    {
    }

    /// <summary>Its section's key in configuration, such as <c>Tcp</c>.</summary>
    internal abstract string Key { get; }

    /// <summary>The key whose presence chooses this link (<c>Serial:PortName</c>, <c>Tcp</c>).</summary>
    internal abstract string ChoiceKey { get; }

    /// <summary>What the link is, for "either … or …": <c>a local serial port</c>.</summary>
    internal abstract string What { get; }

    /// <summary>How to choose it, for "no link is set": <c>Tcp (host:port of a serial-device server)</c>.</summary>
    internal abstract string Hint { get; }

    /// <summary>The key names its section holds, for messages and suggestions.</summary>
    internal abstract IEnumerable<string> KeyNames { get; }

    /// <summary>True when the settings choose this link.</summary>
    internal abstract bool IsChosen { get; }

    /// <summary>Reads its key (a section, or a short value form) from configuration.</summary>
    internal abstract void Read(SettingValue value);

    /// <summary>Adds what is wrong with its settings; <paramref name="client"/> tells which link is chosen.</summary>
    internal abstract void Check(HostLinkClientSettings client, List<HostLinkSettingsProblem> problems);

    /// <summary>The transport for valid settings.</summary>
    internal abstract IHostLinkTransport CreateTransport(HostLinkClientSettings client);
}
