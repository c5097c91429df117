#!/usr/bin/env bash
# Regenerates the box-filtered references in tests/references/box/: every built-in scene at
# 400x300 with 16 samples per pixel (4 x 4 strata), its caustics averaged over each stratum's own
# footprint on the receiver (the FFT ocean: a periodic floor map of 8192 texels per period, whose
# texel the manifest sets against the pixels' footprints), each with its estimated error (the
# caustics one level coarser, the filter at 4 samples per pixel) in manifest.json. Hours of CPU
# in all (docs/accuracy.md gives each scene's time): run it on a machine that does no timing
# work meanwhile, never in CI. Usage: tools/reference/make_box_references.sh [SCENE...]
set -euo pipefail
cd "$(dirname "$0")/../.."
vkwater=${VKWATER:-build/tools/vkwater/vkwater}
out=tests/references/box
mkdir -p "$out"
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(calm underwater box pool lake ocean)
for scene in "${scenes[@]}"; do
    case "$scene" in
        ocean) caustics=(--floor-texels 8192) ;;
        *) caustics=(--footprint-caustics) ;;
    esac
    "$vkwater" reference "scenes/$scene.json" --width 400 --height 300 --spp 16 "${caustics[@]}" --measure-texels \
        --out "$out/$scene.exr" --manifest "$out/manifest.json"
done
