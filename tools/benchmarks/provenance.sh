# Sourced by the benchmark scripts that print a table for the docs: the line above the table that
# says where its figures come from, so that a table copied into a page carries its own date,
# commit, device and machine load (absolute times on the project's shared machines move by 2x).
#
#   source tools/benchmarks/provenance.sh
#   provenance_start              # before the measurements: notes the load average
#   provenance_line VKWATER ...   # after them: prints the line (VKWATER: the binary whose device
#                                 # is named; the rest: what else the reader should know)

provenance_start() {
  provenance_load_before=$(cut -d' ' -f1-3 /proc/loadavg)
}

provenance_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)

provenance_line() {
  local vk=$1
  shift
  local commit device scratch
  commit=$(git -C "$provenance_root" rev-parse --short HEAD 2>/dev/null || echo "an unknown commit")
  git -C "$provenance_root" diff --quiet HEAD 2>/dev/null || commit="$commit with uncommitted changes"
  scratch=$(mktemp -d)
  # The device the renders ran on, as `vkwater render` names it (a 16x16 calm frame, about 0.3 s).
  device=$("$vk" render "$provenance_root/scenes/calm.json" --width 16 --height 16 --out "$scratch/device.exr" 2>/dev/null |
    sed -n 's/^device: \(.*\) (instance .*/\1/p' | head -1)
  rm -rf "$scratch"
  echo "Measured $(date -u +%Y-%m-%d) at $commit on ${device:-an unnamed device}, $(nproc) CPUs;" \
    "load average ${provenance_load_before:-unknown} before and $(cut -d' ' -f1-3 /proc/loadavg) after${*:+; $*}."
}
