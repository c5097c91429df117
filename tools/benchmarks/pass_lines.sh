#!/usr/bin/env bash
# Lines a pass costs, at an older commit and in this tree: for each file, its lines, its code lines
# (neither blank nor only a // comment), and the lines of its execute function (from the line
# that opens the execute lambda, `[...](const Data& d, fg::PassContext& context) {`, to the `});`
# that closes the pass). Prints a Markdown table.
# usage: tools/benchmarks/pass_lines.sh OLD_COMMIT FILE...
set -euo pipefail
cd "$(dirname "$0")/../.."
[ $# -ge 2 ] || { echo "usage: $0 OLD_COMMIT FILE..." >&2; exit 1; }
old=$1
shift

count() {  # stdin: a file's text; prints "lines code execute"
  awk '
    { lines++ }
    /^[[:space:]]*$/ { next }
    /^[[:space:]]*\/\// { next }
    { code++ }
    /PassContext& context\) \{/ { inside = 1 }
    inside { execute++ }
    inside && /^[[:space:]]*}\);/ { inside = 0 }
    END { printf "%d %d %d\n", lines, code, execute }'
}

echo "| file | lines before | lines now | code before | code now | execute before | execute now |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
total=(0 0 0 0 0 0)
for file in "$@"; do
  read -r l0 c0 e0 < <(git show "$old:$file" 2>/dev/null | count || echo "0 0 0")
  read -r l1 c1 e1 < <( ([ -f "$file" ] && cat "$file" || true) | count)
  echo "| $file | $l0 | $l1 | $c0 | $c1 | $e0 | $e1 |"
  values=("$l0" "$l1" "$c0" "$c1" "$e0" "$e1")
  for i in 0 1 2 3 4 5; do total[i]=$((total[i] + values[i])); done
done
echo "| total | ${total[0]} | ${total[1]} | ${total[2]} | ${total[3]} | ${total[4]} | ${total[5]} |"
