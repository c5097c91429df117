#!/usr/bin/env bash
# Regenerates the committed sweeps docs/sweeps/{calm,pool,lake}.{csv,svg}: `vkwater bench` at the
# references' size (400x300) against tests/references/<scene>.exr, over the water (= photon)
# grid, the caustics (off: the flat-surface stand-in; on with the bilinear or the adaptive splat
# kernel) and the godrays (off, or a 32 or 128 beam grid; 128 is the default).
# Usage: docs/sweeps/run.sh [BUILD_DIR] [FRAMES]   (defaults: build, 30 timed frames per setting)
# Run it on a quiet machine: the times are medians of wall-clock frame times.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
frames=${2:-30}
vkwater="$build/tools/vkwater/vkwater"
[ -x "$vkwater" ] || { echo "run.sh: $vkwater not found (build the vkwater target first)" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

godrays='effects.godrays.mode=off|effects.godrays.grid=32|effects.godrays.grid=128'
caustics='effects.caustics.mode=off|effects.caustics.kernel=bilinear|effects.caustics.kernel=adaptive'

sweep() {  # scene, then bench's sweep arguments
    local scene=$1
    shift
    "$vkwater" bench "scenes/$scene.json" --reference "tests/references/$scene.exr" --frames "$frames" \
        --out-dir "$scratch/$scene" "$@"
    cp "$scratch/$scene/sweep.csv" "docs/sweeps/$scene.csv"
    cp "$scratch/$scene/sweep.svg" "docs/sweeps/$scene.svg"
}

# calm: flat water, so the godrays are off by the needs' rule (the analytic in-scatter is
# exact); forcing them on measures what the beams cost and add.
sweep calm --grids 16,64,256 --sweep effects.caustics.mode=on,off \
    --alternatives 'effects.godrays.mode=auto|effects.godrays.mode=on effects.godrays.grid=32|effects.godrays.mode=on effects.godrays.grid=128'
sweep pool --grids 256,512,1024 --alternatives "$caustics" --alternatives "$godrays"
sweep lake --grids 128,256,512 --alternatives "$caustics" --alternatives "$godrays"
