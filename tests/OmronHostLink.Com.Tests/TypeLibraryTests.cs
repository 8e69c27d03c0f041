using System.Globalization;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Runtime.Loader;
using System.Text.RegularExpressions;

namespace OmronHostLink.Com.Tests;

/// <summary>
/// The type library VBA's References and VB6's early binding use: registered by register.cmd, read back under Wine with
/// LoadRegTypeLib (tlbcheck dump), and compared member by member with the .NET interfaces the server implements (names,
/// DISPIDs, vtable order, types) and with the documented Err.Number table; then the server called through the vtable
/// the library describes, as compiled VB6 code calls it (tlbcheck call).
/// </summary>
[Collection(WineCollection.Name)]
public sealed partial class TypeLibraryTests(WineBed bed)
{
    private static readonly TimeSpan Timeout = TimeSpan.FromMinutes(2);

    public static TheoryData<string> Architectures => VbScriptTests.Architectures;

    [SkippableTheory]
    [MemberData(nameof(Architectures))]
    public async Task The_registered_type_library_describes_the_server_as_its_NET_interfaces_do(string architecture)
    {
        Skip.If(architecture == "x86" && bed.Wine32 is null, "No 32-bit Wine for the x86 server: " + bed.X86Status);
        ProcessResult dump = await bed.RunAsync(bed.WineFor(architecture), [Path.Combine(bed.Tools, $"tlbcheck-{architecture}.exe"), "dump"], Timeout);
        dump.ExitCode.Should().Be(0, dump.Output);
        string[] lines = dump.Lines;

        string library = lines[0];
        library.Should().StartWith("library OmronHostLink 1.0");
        library.Should().Contain(architecture == "x64" ? "syskind=3" : "syskind=1", "the x64 server carries a --win64 library and the x86 one a --win32 library");
        library.Should().Contain($@"C:\OmronHostLink.Com\{architecture}\OmronHostLink.Com.comhost.dll");

        Assembly server = LoadServer();
        int pointer = architecture == "x64" ? 8 : 4;
        ExpectInterface(lines, server.GetType("OmronHostLink.Com.IPlc")!, pointer);
        ExpectInterface(lines, server.GetType("OmronHostLink.Com.IPlcStatus")!, pointer);
        ExpectEvents(lines, server.GetType("OmronHostLink.Com.IPlcEvents")!);

        lines.Should().Contain(l => l.StartsWith("type coclass Plc {269D5FC2-B1DB-4DD3-9FF2-AD7640E49483}", StringComparison.Ordinal));
        Section(lines, "type coclass Plc ").Should().Contain("  implements IPlc default").And.Contain("  implements IPlcEvents default source");
        server.GetType("OmronHostLink.Com.Plc")!.GUID.Should().Be(new Guid("269D5FC2-B1DB-4DD3-9FF2-AD7640E49483"));

        Dictionary<string, int> constants = Section(lines, "type enum PlcError ")
            .Select(l => ConstantLine().Match(l)).Where(m => m.Success)
            .ToDictionary(m => m.Groups[1].Value, m => int.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture));
        constants.Should().BeEquivalentTo(new Dictionary<string, int>
        {
            ["ohlErrTimeout"] = Documented.Timeout,
            ["ohlErrFrame"] = Documented.Frame,
            ["ohlErrConnection"] = Documented.Connection,
            ["ohlErrNotOpen"] = Documented.NotOpen,
            ["ohlErrInvalidArgument"] = Documented.InvalidArgument,
            ["ohlErrHostLink"] = Documented.HostLink,
            ["ohlErrEndCode"] = Documented.EndCode,
            ["ohlErrEndCodeRunMode"] = Documented.EndCodeRunMode,
            ["ohlErrFinsEndCode"] = Documented.FinsEndCode,
        });
        Type errors = server.GetType("OmronHostLink.Com.PlcErrors")!;
        foreach ((string name, int value) in constants)
        {
            errors.GetField(name["ohlErr".Length..])!.GetRawConstantValue().Should().Be(value, $"the server raises {name} as the library declares it");
        }
    }

    [SkippableTheory]
    [MemberData(nameof(Architectures))]
    public async Task Early_binding_calls_the_server_through_the_vtable_the_library_declares(string architecture)
    {
        Skip.If(architecture == "x86" && bed.Wine32 is null, "No 32-bit Wine for the x86 server: " + bed.X86Status);
        await using Simulation simulation = await Simulation.StartAsync();
        simulation.Unit0.Mode = PlcMode.Monitor;

        ProcessResult call = await bed.RunAsync(bed.WineFor(architecture), [Path.Combine(bed.Tools, $"tlbcheck-{architecture}.exe"), "call", simulation.Endpoint], Timeout);

        call.ExitCode.Should().Be(0, call.Output);
        call.Lines.Should().HaveCount(6, call.Output);
        call.Lines[..4].Should().Equal(
            $"bits {(architecture == "x64" ? 64 : 32)}",
            "ReadWord D100: ok 1000",
            "ReadReal D300: ok 0",
            "WriteWord D200: ok");
        call.Lines[4].Should().MatchRegex("^ReadStatus: ok MONITOR [0-9]+$");
        call.Lines[5].Should().Be("IsOpen: True");
        simulation.Unit0.ReadWords("D200", 1).Should().Equal(4321);
    }

    /// <summary>
    /// A dual interface: the dispatch half lists each .NET member with its DISPID; the vtable half lists them in the
    /// .NET interface's order, after IDispatch's seven methods, with the types COM interop marshals them as.
    /// </summary>
    private static void ExpectInterface(string[] lines, Type type, int pointer)
    {
        Guid iid = type.GUID;
        string header = $"type interface {type.Name} {{{iid.ToString().ToUpperInvariant()}}}";
        string[] vtable = Section(lines, header + " ");
        vtable.Should().NotBeEmpty($"the library has the vtable interface {type.Name}");
        MethodInfo[] methods = type.GetMethods();
        string[] functions = vtable.Where(l => l.StartsWith("  func ", StringComparison.Ordinal)).ToArray();
        functions.Should().HaveCount(methods.Length, $"{type.Name} has {methods.Length} methods in .NET");
        for (int i = 0; i < methods.Length; i++)
        {
            MethodInfo method = methods[i];
            (string name, string invoke) = method.IsSpecialName && method.Name.StartsWith("get_", StringComparison.Ordinal) ? (method.Name[4..], "propget")
                : method.IsSpecialName && method.Name.StartsWith("set_", StringComparison.Ordinal) ? (method.Name[4..], "propput")
                : (method.Name, "method");
            int dispId = DispId(type, method, name);
            string expected = $"  func {name} id={dispId} {invoke} vft={(7 + i) * pointer} ret=HRESULT params={Parameters(method)}";
            functions[i].Should().Be(expected, $"slot {i} of {type.Name} is {method.Name}");
        }
    }

    private static void ExpectEvents(string[] lines, Type type)
    {
        string[] events = Section(lines, $"type dispatch {type.Name} {{{type.GUID.ToString().ToUpperInvariant()}}}");
        foreach (MethodInfo method in type.GetMethods())
        {
            string parameters = string.Join(",", method.GetParameters().Select(p => VariantType(p.ParameterType, p)));
            events.Should().Contain(l => l.StartsWith($"  func {method.Name} id={method.GetCustomAttribute<DispIdAttribute>()!.Value} method ", StringComparison.Ordinal) && l.EndsWith("params=" + parameters, StringComparison.Ordinal),
                $"the event {method.Name} is declared as in .NET");
        }
    }

    private static int DispId(Type type, MethodInfo method, string name)
    {
        if (method.IsSpecialName)
        {
            return type.GetProperty(name)!.GetCustomAttribute<DispIdAttribute>()!.Value;
        }

        return method.GetCustomAttribute<DispIdAttribute>()!.Value;
    }

    /// <summary>What COM interop passes for each parameter, then the result as [out, retval].</summary>
    private static string Parameters(MethodInfo method)
    {
        var parts = method.GetParameters().Select(p => VariantType(p.ParameterType, p) + (p.IsOptional ? "[optional]" : "")).ToList();
        if (method.ReturnType != typeof(void))
        {
            parts.Add($"PTR({VariantType(method.ReturnType, method.ReturnParameter)})[out][retval]");
        }

        return string.Join(",", parts);
    }

    private static string VariantType(Type type, ParameterInfo parameter)
    {
        if (type == typeof(bool))
        {
            parameter.GetCustomAttribute<MarshalAsAttribute>()?.Value.Should().Be(UnmanagedType.VariantBool, $"{parameter.Member.Name} passes a VB Boolean");
            return "BOOL";
        }

        return type == typeof(int) ? "I4"
            : type == typeof(float) ? "R4"
            : type == typeof(double) ? "R8"
            : type == typeof(string) ? "BSTR"
            : type == typeof(object) ? "VARIANT"
            : type.IsInterface ? $"PTR(USERDEFINED {type.Name})"
            : throw new InvalidOperationException($"{type} has no VB type in this test");
    }

    private static string[] Section(string[] lines, string headerStart)
    {
        int start = Array.FindIndex(lines, l => l.StartsWith(headerStart, StringComparison.Ordinal));
        start.Should().BeGreaterThanOrEqualTo(0, $"the dump has a line starting '{headerStart}':\n{string.Join('\n', lines)}");
        return lines.Skip(start + 1).TakeWhile(l => l.StartsWith("  ", StringComparison.Ordinal)).ToArray();
    }

    /// <summary>
    /// The server's interfaces, from the x64 build: the x86 assembly is the same source compiled for a 32-bit process,
    /// which this 64-bit test process cannot load.
    /// </summary>
    private Assembly LoadServer()
    {
        var context = new AssemblyLoadContext("OmronHostLink.Com", isCollectible: true);
        return context.LoadFromAssemblyPath(Path.Combine(bed.ComFolder, "x64", "OmronHostLink.Com.dll"));
    }

    [GeneratedRegex(@"^  const (\w+) = (-?\d+)$")]
    private static partial Regex ConstantLine();
}
