using System.Runtime.InteropServices;
using System.Runtime.InteropServices.ComTypes;
using Microsoft.Win32;

namespace OmronHostLink.Com;

/// <summary>
/// Registers the type library embedded in the comhost when <c>regsvr32</c> registers the server, and removes it with
/// <c>regsvr32 /u</c>. The comhost registers only the class and its ProgId; the <c>TypeLib</c> key (which VBA's
/// References list and VB6's early binding read), the interfaces' keys and the class's <c>TypeLib</c> value are written
/// here, by OLE Automation's own <c>RegisterTypeLib</c>, from the server's registration function.
/// </summary>
internal static class TypeLibrary
{
    /// <summary>The library's GUID: the <c>uuid</c> of the IDL's <c>library</c>, and this assembly's <see cref="GuidAttribute"/>.</summary>
    public const string Id = "10D060FD-2EDB-4935-AC9B-0064C3B500C7";

    private const int RegisterKindNone = 2;

    /// <summary>The comhost beside this assembly: <c>OmronHostLink.Com.comhost.dll</c>.</summary>
    public static string ComHostPath
    {
        get
        {
            string assembly = typeof(TypeLibrary).Assembly.Location;
            return Path.Combine(Path.GetDirectoryName(assembly)!, Path.GetFileNameWithoutExtension(assembly) + ".comhost.dll");
        }
    }

    /// <summary>Registers the library for the class <paramref name="type"/>.</summary>
    /// <exception cref="COMException">The comhost carries no type library (built without widl), or the registry refused.</exception>
    public static void Register(Type type)
    {
        string path = ComHostPath;
        ITypeLib library;
        try
        {
            library = NativeMethods.LoadTypeLibEx(path, RegisterKindNone);
        }
        catch (COMException e)
        {
            throw new COMException($"{path} carries no type library (it was built without widl); VBA and VB6 could not find the server's members. Install the server from the release zip. ({e.Message})", e.ErrorCode);
        }

        try
        {
            NativeMethods.RegisterTypeLib(library, path, Path.GetDirectoryName(path));
        }
        finally
        {
            Marshal.ReleaseComObject(library);
        }

        // RegAsm wrote these too: the class's library, for tools that look for it from the class.
        string clsid = type.GUID.ToString("B").ToUpperInvariant();
        using RegistryKey key = Registry.LocalMachine.CreateSubKey($@"SOFTWARE\Classes\CLSID\{clsid}\TypeLib");
        key.SetValue(null, "{" + Id + "}");
        using RegistryKey version = Registry.LocalMachine.CreateSubKey($@"SOFTWARE\Classes\CLSID\{clsid}\Version");
        version.SetValue(null, "1.0");
    }

    /// <summary>Removes the library's registration; a library that is not registered is not an error.</summary>
    public static void Unregister()
    {
        var id = new Guid(Id);
        SYSKIND kind = Environment.Is64BitProcess ? SYSKIND.SYS_WIN64 : SYSKIND.SYS_WIN32;
        int hr = NativeMethods.UnRegisterTypeLib(id, 1, 0, 0, kind);
        const int TypeLibraryNotRegistered = unchecked((int)0x8002801D);
        if (hr < 0 && hr != TypeLibraryNotRegistered)
        {
            Marshal.ThrowExceptionForHR(hr);
        }
    }
}
