#!/usr/bin/env bash
# Regenerates the committed sweeps docs/sweeps/{calm,pool,lake}.{csv,svg}: `vkwater bench` at the
# references' size (400x300) against tests/references/<scene>.exr, over the water (= photon)
# grid, the caustics (off: the flat-surface stand-in; on with the bilinear or the adaptive splat
# kernel, or the baselines: the footprint kernel, Tipprasert 2006's area ratio, Guardado & Sánchez-Crespo 2004's procedural
# caustic, and Ojeda & Susín 2013's camera-space splats) and the godrays (off, or a 32 or 128 beam
# grid; 128 is the default).
# Usage: docs/sweeps/run.sh [BUILD_DIR] [FRAMES] [SCENE...]
#   (defaults: build, 30 timed frames per setting, calm pool lake pool-map-scale)
# Run it on a quiet machine: the times are medians of wall-clock frame times.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
frames=${2:-30}
shift $(($# < 2 ? $# : 2))
scenes=${*:-calm pool lake pool-map-scale}
vkwater="$build/tools/vkwater/vkwater"
[ -x "$vkwater" ] || { echo "run.sh: $vkwater not found (build the vkwater target first)" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

godrays='effects.godrays.mode=off|effects.godrays.grid=32|effects.godrays.grid=128'
caustics='effects.caustics.mode=off|effects.caustics.kernel=bilinear|effects.caustics.kernel=adaptive|effects.caustics.kernel=footprint|effects.caustics.method=procedural|effects.caustics.splat=camera-space'

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
for scene in $scenes; do
    case $scene in
    calm)
        sweep calm --grids 16,64,256 --sweep effects.caustics.mode=on,off \
            --alternatives 'effects.godrays.mode=auto|effects.godrays.mode=on effects.godrays.grid=32|effects.godrays.mode=on effects.godrays.grid=128'
        ;;
    pool) sweep pool --grids 256,512,1024 --alternatives "$caustics" --alternatives "$godrays" ;;
    lake) sweep lake --grids 128,256,512 --alternatives "$caustics" --alternatives "$godrays" ;;
    pool-map-scale)  # the caustic map's resolution against the photon grid, godrays off
        "$vkwater" bench scenes/pool.json --reference tests/references/pool.exr --frames "$frames" \
            --out-dir "$scratch/pool-map-scale" --grids 256,512,1024 --sweep effects.caustics.map_scale=1,2,4 \
            --set effects.godrays.mode=off
        cp "$scratch/pool-map-scale/sweep.csv" docs/sweeps/pool-map-scale.csv
        cp "$scratch/pool-map-scale/sweep.svg" docs/sweeps/pool-map-scale.svg
        ;;
    *) echo "run.sh: no sweep for '$scene' (accepted: calm, pool, lake, pool-map-scale)" >&2; exit 1 ;;
    esac
done
