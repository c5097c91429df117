#!/usr/bin/env bash
# scaled_samples.sh [SCENE ...]
#
# What samples per pixel buy below full resolution scale, where the frame is stretched to the
# output after its samples are averaged: each scene at 400x300 with --render-scale 1, 0.75 and 0.5,
# each at 1 and 4 samples per pixel, its image relMSE against its box-filtered reference
# (tests/references/box/SCENE.exr), and the rows at one sample that the same error stands for
# (interpolated in log2 between the scales' one-sample errors, as the budget's error model does;
# "-" outside them). The budget's error model counts the samples as rows at full scale only
# (tools/vkwater/budget/error_model.hpp); this table is why. Errors only: the machine's load does
# not change them. Default scenes: pool lake ocean. VKWATER=PATH for another build.
set -euo pipefail
cd "$(dirname "$0")/../.."
vk=${VKWATER:-build/tools/vkwater/vkwater}
source tools/benchmarks/provenance.sh
provenance_start
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(pool lake ocean)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

relmse() {  # SCENE SCALE SPP
  "$vk" render "scenes/$1.json" --width 400 --height 300 --render-scale "$2" --spp "$3" --out "$out/x.exr" > /dev/null 2>&1
  "$vk" compare "$out/x.exr" "tests/references/box/$1.exr" | sed -n 's/^relMSE \([0-9.e+-]*\).*/\1/p'
}

echo "| scene | render scale | relMSE, 1 sample | relMSE, 4 samples | rows the 4 samples stand for, over the scale's |"
echo "| --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  declare -A one=()
  for scale in 1 0.75 0.5; do one[$scale]=$(relmse "$scene" "$scale" 1); done
  for scale in 1 0.75 0.5; do
    four=$(relmse "$scene" "$scale" 4)
    # The scale s' (between the measured ones, above s) whose one-sample error equals the
    # 4 samples' at s, in log2: s' / s is the rows factor.
    factor=$(awk -v s="$scale" -v e="$four" -v e1="${one[1]}" -v e075="${one[0.75]}" -v e05="${one[0.5]}" 'BEGIN {
      n = split("1 0.75 0.5", sc, " "); err[1] = e1; err[2] = e075; err[3] = e05
      for (i = 1; i < n; i++) {
        hi = err[i]; lo = err[i + 1]
        if (e >= hi && e <= lo && lo > hi) {
          t = (e - hi) / (lo - hi)
          rows = exp(log(sc[i]) + t * (log(sc[i + 1]) - log(sc[i])))
          printf "%.2f", rows / s; exit
        }
      }
      printf "-" }')
    echo "| $scene | $scale | ${one[$scale]} | $four | $factor |"
  done
done
echo
echo "*$(provenance_line "$vk" "400x300 against tests/references/box; errors only")*"
