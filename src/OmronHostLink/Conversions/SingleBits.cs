#if !NET
using System.Runtime.InteropServices;
#endif

namespace OmronHostLink;

/// <summary>Reinterprets float bits; netstandard2.0 lacks BitConverter.SingleToInt32Bits.</summary>
internal static class SingleBits
{
#if NET
    public static int ToInt32(float value) => BitConverter.SingleToInt32Bits(value);

    public static float ToSingle(int bits) => BitConverter.Int32BitsToSingle(bits);
#else
    public static int ToInt32(float value) => new Overlay { Single = value }.Int32;

    public static float ToSingle(int bits) => new Overlay { Int32 = bits }.Single;

    /// <summary>The same four bytes seen as either type, in safe code.</summary>
    [StructLayout(LayoutKind.Explicit)]
    private struct Overlay
    {
        [FieldOffset(0)]
        public float Single;

        [FieldOffset(0)]
        public int Int32;
    }
#endif
}
