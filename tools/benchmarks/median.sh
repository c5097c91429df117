# Sourced by the benchmark scripts: `median` prints the median of the numbers on its standard input,
# one per line (the mean of the middle two for an even count).
#
#   source tools/benchmarks/median.sh
#   printf '%s\n' 3 1 2 | median    # 2

median() {
  sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
