using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Planning;

/// <summary>QQ in C-mode plans: per unit, one registered QQIR where it costs fewer characters a cycle than area reads, in fewer reads.</summary>
public sealed partial class ReadPlanner
{
    /// <summary>
    /// Per unit that may use QQ, whether one QQIR of some of its tags' words (the dearest to read by area, up to 128 items) plus area
    /// reads of the rest costs fewer characters a cycle than the area reads alone, in fewer reads; if so the unit's area
    /// reads are replaced. A word that only bit tags need is registered as those bits where that is shorter (one character each
    /// in the answer instead of four); a timer/counter PV comes with its completion flag (five characters, two items).
    /// The registration is not counted here: it is paid once, not per cycle.
    /// </summary>
    private void PlanCompound(SortedDictionary<(int Unit, PlcArea Area, int Bank), List<(int Start, int End)>> spaces, List<PlannedRead> reads, CompoundNeeds needs)
    {
        foreach (int unit in spaces.Keys.Select(k => k.Unit).Distinct().Where(PlansCompound).ToArray())
        {
            var eligible = spaces.Where(s => s.Key.Unit == unit).ToArray();
            List<PlannedRead> current = reads.Where(r => r.Kind == PlannedReadKind.CModeArea && r.Unit == unit).ToList();
            double currentCost = current.Sum(r => r.Characters + (r.Exchanges * _turnaroundChars));

            // The clusters dearest per word when read alone go to QQ first.
            var clusters = eligible
                .SelectMany(s => Clusters(s.Value).Select(c => (s.Key.Area, s.Key.Bank, c.Start, c.End)))
                .OrderByDescending(c => RangeCost(c.Area, c.End - c.Start) / (c.End - c.Start))
                .ThenBy(c => c.Area).ThenBy(c => c.Start)
                .ToList();
            var items = new List<CompoundItem>();
            var addresses = new List<PlcAddress>();
            int weight = 0;
            var rest = new Dictionary<(PlcArea Area, int Bank), List<(int Start, int End)>>();
            foreach ((PlcArea area, int bank, int start, int end) in clusters)
            {
                var cluster = new List<PlcAddress>();
                for (int w = start; w < end; w++)
                {
                    cluster.AddRange(needs.ItemsOf(unit, PlcAddress.WordOf(area, w, bank)));
                }

                CompoundItem[] clusterItems = cluster.Select(CompoundItem.For).ToArray();
                int clusterWeight = clusterItems.Sum(i => i.Weight);
                if (weight + clusterWeight <= CompoundItem.MaxWeight)
                {
                    items.AddRange(clusterItems);
                    addresses.AddRange(cluster);
                    weight += clusterWeight;
                    continue;
                }

                if (!rest.TryGetValue((area, bank), out List<(int, int)>? list))
                {
                    rest[(area, bank)] = list = new List<(int, int)>();
                }

                list.Add((start, end));
            }

            var restReads = new List<PlannedRead>();
            foreach (KeyValuePair<(PlcArea Area, int Bank), List<(int Start, int End)>> space in rest)
            {
                PlanSpace(unit, space.Key.Area, space.Key.Bank, Clusters(space.Value), restReads, new SortedDictionary<int, List<PlcAddress[]>>());
            }

            int chars = CompoundAnswerCharacters(CompoundCommands.DataLength(items), out int exchanges);
            double compoundCost = chars + (exchanges * _turnaroundChars) + restReads.Sum(r => r.Characters + (r.Exchanges * _turnaroundChars));
            // QQ must replace reads, not only shave characters off one: a unit holds one registration (which another
            // tag set may take), it costs a QQMR whenever the PLC lost it, and with Auto an MM first.
            if (items.Count == 0 || compoundCost >= currentCost || 1 + restReads.Count >= current.Count)
            {
                continue;
            }

            // Area reads of the same words, for a cycle that would have to pay the registration.
            var fallback = new List<PlannedRead>();
            foreach (IGrouping<(PlcArea Area, int Bank), PlcAddress> space in addresses.Select(a => a.AsWord()).GroupBy(w => (w.Area, w.Bank)))
            {
                var spans = space.Select(w => (w.Word, w.Word + 1)).ToList();
                PlanSpace(unit, space.Key.Area, space.Key.Bank, Clusters(spans), fallback, new SortedDictionary<int, List<PlcAddress[]>>());
            }

            int at = reads.IndexOf(current[0]);
            reads.RemoveAll(current.Contains);
            var compound = new PlannedRead(PlannedReadKind.CModeCompound, unit, addresses[0], addresses.Count, addresses.ToArray(), chars, exchanges, fallback, CompoundRegisterCharacters(items.Count, out _));
            reads.InsertRange(Math.Min(at, reads.Count), restReads.Prepend(compound));
        }
    }

    /// <summary>What a tag set needs of each word it reads: the whole word, or (bit tags alone) some of its bits.</summary>
    private sealed class CompoundNeeds
    {
        private readonly HashSet<(int Unit, PlcAddress Word)> _words = new();
        private readonly Dictionary<(int Unit, PlcAddress Word), SortedSet<int>> _bits = new();

        /// <summary>Notes what <paramref name="tag"/> of <paramref name="unit"/> reads (completion flags are not QQ's).</summary>
        public void Add(int unit, PlcTag tag)
        {
            if (tag.Address.IsBit)
            {
                if (!_bits.TryGetValue((unit, tag.Address.AsWord()), out SortedSet<int>? bits))
                {
                    _bits[(unit, tag.Address.AsWord())] = bits = new SortedSet<int>();
                }

                bits.Add(tag.Address.Bit);
                return;
            }

            for (int i = 0; i < tag.WordCount; i++)
            {
                _words.Add((unit, tag.Address.Offset(i)));
            }
        }

        /// <summary>
        /// The QQ items that read <paramref name="word"/> for the tags: its bits, where only bit tags need it, the area
        /// has bit items and they answer in fewer characters than the word (with their commas); else the word.
        /// </summary>
        public IEnumerable<PlcAddress> ItemsOf(int unit, PlcAddress word)
        {
            if (!_words.Contains((unit, word))
                && _bits.TryGetValue((unit, word), out SortedSet<int>? bits)
                && CompoundItem.ReadsBits(word.Area)
                && bits.Count * (CompoundItem.BitAnswerLength + 1) < CompoundItem.WordAnswerLength + 1)
            {
                return bits.Select(word.WithBit);
            }

            return new[] { word };
        }
    }
}
