using System.Runtime.InteropServices;

namespace OmronHostLink.Com;

/// <summary>
/// The server's interface, as <c>OmronHostLink.Com.idl</c> declares it: a dual interface, so VBScript calls it by name
/// and VB6/VBA early binding through its vtable. The members' order, DISPIDs and types must match the IDL exactly
/// (the tests compare them with the compiled type library).
/// </summary>
/// <remarks>
/// The connection properties (<see cref="PortName"/> to <see cref="ReadRetries"/>) describe the next <see cref="Open"/>
/// and read back what is open; a value is checked by <c>Open</c>, never by its setter (see docs/windows.md for why).
/// <see cref="UnitNumber"/> may change while open and is checked by the next call.
/// </remarks>
[ComVisible(true)]
[Guid("825F70F9-639A-4F6B-883B-26437E57D1A8")]
[InterfaceType(ComInterfaceType.InterfaceIsDual)]
public interface IPlc
{
    /// <summary>The local serial port (<c>COM3</c>); empty for a serial-device server.</summary>
    [DispId(1)]
    string PortName { get; set; }

    /// <summary>Line speed in bits per second. Default 9600.</summary>
    [DispId(2)]
    int BaudRate { get; set; }

    /// <summary>Data bits, 7 or 8. Default 7.</summary>
    [DispId(3)]
    int DataBits { get; set; }

    /// <summary>Parity: <c>E</c>, <c>O</c> or <c>N</c> (or Even, Odd, None). Default E.</summary>
    [DispId(4)]
    string Parity { get; set; }

    /// <summary>Stop bits, 1 or 2. Default 2.</summary>
    [DispId(5)]
    int StopBits { get; set; }

    /// <summary>A serial-device server's host name or address, instead of <see cref="PortName"/>.</summary>
    [DispId(6)]
    string Host { get; set; }

    /// <summary>The serial-device server's TCP port.</summary>
    [DispId(7)]
    int TcpPort { get; set; }

    /// <summary>The unit number 0-31 the calls address; may change while open (units on one multidrop line).</summary>
    [DispId(8)]
    int UnitNumber { get; set; }

    /// <summary><c>CMode</c> (default) or <c>Fins</c>.</summary>
    [DispId(9)]
    string CommandSet { get; set; }

    /// <summary>How long the PLC may take to start answering, in milliseconds. Default 300.</summary>
    [DispId(10)]
    int TurnaroundAllowance { get; set; }

    /// <summary>How many times a read is repeated after a timeout or a damaged answer. Default 2.</summary>
    [DispId(11)]
    int ReadRetries { get; set; }

    /// <summary>True between <see cref="Open"/> and <see cref="Close"/>.</summary>
    [DispId(12)]
    bool IsOpen { [return: MarshalAs(UnmanagedType.VariantBool)] get; }

    /// <summary>Where the link goes (<c>COM3 9600 7E2</c>, <c>127.0.0.1:9600</c>); empty before <see cref="Open"/>.</summary>
    [DispId(13)]
    string Description { get; }

    /// <summary>Opens the link from a connection string, or from the properties when it is empty.</summary>
    /// <param name="connection"><c>COM3:9600,E,7,2</c>, <c>tcp://host:port</c>, then <c>;Key=Value</c> settings.</param>
    [DispId(20)]
    void Open(string connection = "");

    /// <summary>Stops a watch and closes the link at once. Harmless when closed.</summary>
    [DispId(21)]
    void Close();

    /// <summary>Reads one word, 0-65535.</summary>
    [DispId(30)]
    int ReadWord(string address);

    /// <summary>Reads <paramref name="count"/> words as one command: an array of Long.</summary>
    [DispId(31)]
    object ReadWords(string address, int count);

    /// <summary>Writes one word: 0-65535, or -32768 to -1 for the same bits (a VB Integer).</summary>
    [DispId(32)]
    void WriteWord(string address, int value);

    /// <summary>Writes an array of words as one command.</summary>
    [DispId(33)]
    void WriteWords(string address, object values);

    /// <summary>Reads one bit.</summary>
    [DispId(34)]
    [return: MarshalAs(UnmanagedType.VariantBool)]
    bool ReadBit(string address);

    /// <summary>Writes one bit (FINS; C-mode only with read-modify-write allowed).</summary>
    [DispId(35)]
    void WriteBit(string address, [MarshalAs(UnmanagedType.VariantBool)] bool value);

    /// <summary>Reads a 4-digit BCD word, 0-9999.</summary>
    [DispId(36)]
    int ReadBcd(string address);

    /// <summary>Writes 0-9999 as a 4-digit BCD word.</summary>
    [DispId(37)]
    void WriteBcd(string address, int value);

    /// <summary>Reads a REAL (two words, low word first).</summary>
    [DispId(38)]
    float ReadReal(string address);

    /// <summary>Writes a REAL.</summary>
    [DispId(39)]
    void WriteReal(string address, float value);

    /// <summary>Reads an LREAL (four words).</summary>
    [DispId(40)]
    double ReadLReal(string address);

    /// <summary>Writes an LREAL.</summary>
    [DispId(41)]
    void WriteLReal(string address, double value);

    /// <summary>Reads a DINT (two words, low word first).</summary>
    [DispId(42)]
    int ReadDint(string address);

    /// <summary>Writes a DINT.</summary>
    [DispId(43)]
    void WriteDint(string address, int value);

    /// <summary>Reads ASCII text, two characters a word, up to <paramref name="length"/> characters or the first NUL.</summary>
    [DispId(44)]
    string ReadString(string address, int length);

    /// <summary>Writes ASCII text, two characters a word.</summary>
    [DispId(45)]
    void WriteString(string address, string text);

    /// <summary>Reads one tag (<c>D100</c>, <c>D100:float</c>, <c>D20:bcd</c>, <c>CIO 10.03</c>).</summary>
    [DispId(46)]
    object Read(string tag);

    /// <summary>Writes one tag's value.</summary>
    [DispId(47)]
    void Write(string tag, object value);

    /// <summary>Reads tags in the fewest commands: an array of values in the tags' order.</summary>
    [DispId(48)]
    object ReadTags(object tags);

    /// <summary>Reads the operating mode, status word and FAL/FALS message.</summary>
    [DispId(50)]
    IPlcStatus ReadStatus();

    /// <summary>Reads the operating mode: <c>PROGRAM</c>, <c>MONITOR</c> or <c>RUN</c>.</summary>
    [DispId(51)]
    string ReadMode();

    /// <summary>Changes the operating mode: <c>PROGRAM</c>, <c>MONITOR</c> or <c>RUN</c>.</summary>
    [DispId(52)]
    void SetMode(string mode);

    /// <summary>Reads the PLC's error information, clearing it afterwards when <paramref name="clear"/> is true.</summary>
    [DispId(53)]
    string ReadErrors([MarshalAs(UnmanagedType.VariantBool)] bool clear = false);

    /// <summary>Reads the PLC's model.</summary>
    [DispId(54)]
    string ReadModel();

    /// <summary>Sends TEST and returns the round trip in milliseconds.</summary>
    [DispId(55)]
    double Test();

    /// <summary>Watches tags every <paramref name="intervalMilliseconds"/>: events on this thread, latest values kept.</summary>
    [DispId(60)]
    void Watch(object tags, int intervalMilliseconds);

    /// <summary>Stops the watch; no event is raised after it returns.</summary>
    [DispId(61)]
    void StopWatch();

    /// <summary>True while a watch runs.</summary>
    [DispId(62)]
    bool IsWatching { [return: MarshalAs(UnmanagedType.VariantBool)] get; }

    /// <summary>The latest value of a watched tag; Empty before its first read.</summary>
    [DispId(63)]
    object WatchedValue(string tag);

    /// <summary>Waits up to the timeout for changes; returns the tags that changed since the last call, or an empty array.</summary>
    [DispId(64)]
    object WaitForChanges(int timeoutMilliseconds);

    /// <summary>Why the watch cannot read, while it cannot; empty otherwise.</summary>
    [DispId(65)]
    string WatchError { get; }
}
