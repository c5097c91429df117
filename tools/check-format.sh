#!/usr/bin/env bash
# Fails, naming each file, when a C++ source of the repository differs from what the committed
# .clang-format makes of it. clang-format-14 is pinned (tools/install-deps.sh installs it): other
# versions format a few constructs differently. `tools/check-format.sh --fix` formats in place.
set -euo pipefail
cd "$(dirname "$0")/.."

formatter=clang-format-14
if ! command -v "$formatter" > /dev/null; then
  echo "check-format: $formatter not found (tools/install-deps.sh installs it)" >&2
  exit 1
fi

# The tracked and new (not ignored) sources when this is a git checkout; every source under the tree otherwise.
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find engine passes library include examples tools tests -name '*.cpp' -o -name '*.hpp' -o -name '*.h' | sort)
fi

if [ "${1:-}" = "--fix" ]; then
  "$formatter" -i "${files[@]}"
  echo "check-format: formatted ${#files[@]} files"
  exit 0
fi

unformatted=()
for file in "${files[@]}"; do
  [ -f "$file" ] || continue
  if ! "$formatter" --dry-run -Werror "$file" > /dev/null 2>&1; then unformatted+=("$file"); fi
done
if [ "${#unformatted[@]}" -gt 0 ]; then
  printf 'check-format: not formatted by .clang-format: %s\n' "${unformatted[@]}" >&2
  echo "check-format: ${#unformatted[@]} of ${#files[@]} files; run tools/check-format.sh --fix" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted"
