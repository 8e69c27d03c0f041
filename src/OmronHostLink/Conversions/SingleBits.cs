namespace OmronHostLink;

/// <summary>Reinterprets float bits; netstandard2.0 lacks BitConverter.SingleToInt32Bits.</summary>
internal static class SingleBits
{
#if NET
    public static int ToInt32(float value) => BitConverter.SingleToInt32Bits(value);

    public static float ToSingle(int bits) => BitConverter.Int32BitsToSingle(bits);
#else
    public static unsafe int ToInt32(float value) => *(int*)&value;

    public static unsafe float ToSingle(int bits) => *(float*)&bits;
#endif
}
