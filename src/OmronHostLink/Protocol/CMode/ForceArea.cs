namespace OmronHostLink.Protocol.CMode;

/// <summary>The areas KS, KR and FK force bits in, with the four-character names the commands carry.</summary>
internal enum ForceArea
{
    /// <summary><c>CIO </c>.</summary>
    Cio,

    /// <summary><c>LR  </c>.</summary>
    Lr,

    /// <summary><c>HR  </c>.</summary>
    Holding,

    /// <summary><c>AR  </c>.</summary>
    Auxiliary,

    /// <summary><c>TIM </c>: a timer's completion flag (bit field 00).</summary>
    Timer,

    /// <summary><c>CNT </c>: a counter's completion flag (bit field 00).</summary>
    Counter,
}

/// <summary>Names and limits of <see cref="ForceArea"/>.</summary>
internal static class ForceAreaInfo
{
    /// <summary>The four-character name, space padded.</summary>
    public static string Name(ForceArea area) => area switch
    {
        ForceArea.Cio => "CIO ",
        ForceArea.Lr => "LR  ",
        ForceArea.Holding => "HR  ",
        ForceArea.Auxiliary => "AR  ",
        ForceArea.Timer => "TIM ",
        ForceArea.Counter => "CNT ",
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, "Unknown force area."),
    };

    /// <summary>Finds the area of a four-character name.</summary>
    public static bool TryParse(ReadOnlySpan<byte> name, out ForceArea area)
    {
        foreach (ForceArea candidate in new[] { ForceArea.Cio, ForceArea.Lr, ForceArea.Holding, ForceArea.Auxiliary, ForceArea.Timer, ForceArea.Counter })
        {
            string n = Name(candidate);
            if (name.Length == 4 && name[0] == n[0] && name[1] == n[1] && name[2] == n[2] && name[3] == n[3])
            {
                area = candidate;
                return true;
            }
        }

        area = default;
        return false;
    }

    /// <summary>Number of words (or timers/counters) of the area.</summary>
    public static int Size(ForceArea area) => area switch
    {
        ForceArea.Cio => CModeAreaInfo.Size(CModeArea.Cio),
        ForceArea.Lr => CModeAreaInfo.Size(CModeArea.Lr),
        ForceArea.Holding => CModeAreaInfo.Size(CModeArea.Holding),
        ForceArea.Auxiliary => CModeAreaInfo.Size(CModeArea.Auxiliary),
        _ => CModeAreaInfo.CounterOffset,
    };

    /// <summary>Checks a word and bit for a force command.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The word or bit is out of range.</exception>
    public static void Check(ForceArea area, int word, int bit)
    {
        if (word < 0 || word >= Size(area))
        {
            throw new ArgumentOutOfRangeException(nameof(word), word, $"{Name(area).Trim()} {word} is outside 0-{Size(area) - 1}.");
        }

        bool flag = area is ForceArea.Timer or ForceArea.Counter;
        if (flag ? bit != 0 : (uint)bit > 15)
        {
            throw new ArgumentOutOfRangeException(nameof(bit), bit, flag ? "Timer and counter flags take bit 00." : $"Bit must be 0-15; it was {bit}.");
        }
    }
}
