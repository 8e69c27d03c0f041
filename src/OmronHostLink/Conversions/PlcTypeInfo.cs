namespace OmronHostLink;

/// <summary>
/// The .NET types the generic reads and writes take (<c>ReadAsync&lt;T&gt;</c>, <c>WriteAsync&lt;T&gt;</c>), each with
/// the <see cref="PlcValueType"/> that <see cref="PlcValueCodec"/> converts it as: the one table the generic members
/// dispatch through.
/// </summary>
internal static class PlcTypeInfo
{
    private static readonly (Type Type, PlcValueType ValueType)[] Table =
    [
        (typeof(bool), PlcValueType.Bit),
        (typeof(short), PlcValueType.Int16),
        (typeof(ushort), PlcValueType.UInt16),
        (typeof(int), PlcValueType.Int32),
        (typeof(uint), PlcValueType.UInt32),
        (typeof(float), PlcValueType.Float),
        (typeof(double), PlcValueType.Double),
        (typeof(Bcd16), PlcValueType.Bcd),
        (typeof(Bcd32), PlcValueType.Bcd32),
    ];

    /// <summary>The supported types as a user reads them in a message.</summary>
    public const string SupportedTypes =
        "bool (a bit), short (Int16), ushort (UInt16), int (Int32), uint (UInt32), float (Single), double (Double), Bcd16 and Bcd32";

    public static PlcValueType? Find(Type type)
    {
        foreach ((Type t, PlcValueType valueType) in Table)
        {
            if (t == type)
            {
                return valueType;
            }
        }

        return null;
    }
}

/// <summary>The entry of <typeparamref name="T"/> in <see cref="PlcTypeInfo"/>, looked up once per type.</summary>
/// <typeparam name="T">The .NET type.</typeparam>
internal static class PlcTypeInfo<T>
    where T : struct
{
    private static readonly PlcValueType? Found = PlcTypeInfo.Find(typeof(T));

    /// <summary>The value type of <typeparamref name="T"/>.</summary>
    /// <param name="member">The generic member asked for, for the message.</param>
    /// <exception cref="NotSupportedException"><typeparamref name="T"/> is not in the table.</exception>
    public static PlcValueType Get(string member)
        => Found ?? throw new NotSupportedException(
            $"{member}<{typeof(T).Name}> is not supported: the generic reads and writes take {PlcTypeInfo.SupportedTypes}.");

    // The casts through object are per-T specialisations the JIT compiles to plain moves: no boxing.
    public static PlcValue ToValue(T value) => Found switch
    {
        PlcValueType.Bit => PlcValue.FromBit((bool)(object)value),
        PlcValueType.Int16 => PlcValue.FromInt16((short)(object)value),
        PlcValueType.UInt16 => PlcValue.FromUInt16((ushort)(object)value),
        PlcValueType.Int32 => PlcValue.FromInt32((int)(object)value),
        PlcValueType.UInt32 => PlcValue.FromUInt32((uint)(object)value),
        PlcValueType.Float => PlcValue.FromSingle((float)(object)value),
        PlcValueType.Double => PlcValue.FromDouble((double)(object)value),
        PlcValueType.Bcd => PlcValue.FromBcd(((Bcd16)(object)value).Value),
        PlcValueType.Bcd32 => PlcValue.FromBcd32(((Bcd32)(object)value).Value),
        _ => throw new NotSupportedException(typeof(T).Name),
    };

    public static T FromValue(PlcValue value) => Found switch
    {
        PlcValueType.Bit => (T)(object)value.ToBoolean(),
        PlcValueType.Int16 => (T)(object)value.ToInt16(),
        PlcValueType.UInt16 => (T)(object)value.ToUInt16(),
        PlcValueType.Int32 => (T)(object)value.ToInt32(),
        PlcValueType.UInt32 => (T)(object)value.ToUInt32(),
        PlcValueType.Float => (T)(object)value.ToSingle(),
        PlcValueType.Double => (T)(object)value.ToDouble(),
        PlcValueType.Bcd => (T)(object)new Bcd16(value.ToInt32()),
        PlcValueType.Bcd32 => (T)(object)new Bcd32(value.ToInt32()),
        _ => throw new NotSupportedException(typeof(T).Name),
    };
}
