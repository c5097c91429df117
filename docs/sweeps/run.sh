#!/usr/bin/env bash
# Regenerates the committed sweeps docs/sweeps/{calm,pool,lake}.{csv,svg}: `vkwater bench` at the
# references' size (400x300) against tests/references/<scene>.exr, over the water (= photon)
# grid, the caustics (off: the flat-surface stand-in; on with the bilinear or the adaptive splat
# kernel, or the baselines: the footprint kernel, Tipprasert 2006's area ratio, Guardado & Sánchez-Crespo 2004's procedural
# caustic, and Ojeda & Susín 2013's camera-space splats) and the godrays (off, or a 32 or 128 beam
# grid; the default is 64); and docs/sweeps/godrays-{pool,lake,ocean}.{csv,svg}: the godray methods
# alone (lines over 32 to 256 beams per side, marched with 8 to 64 steps, each at half and full
# resolution) at the scene's own grid, to be read by the in-scatter layer's error against time.
# Usage: docs/sweeps/run.sh [BUILD_DIR] [FRAMES] [SCENE...]
#   (defaults: build, 30 timed frames per setting, calm pool lake pool-map-scale
#    godrays-pool godrays-lake godrays-ocean)
# Run it on a quiet machine: the times are medians of wall-clock frame times.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
frames=${2:-30}
shift $(($# < 2 ? $# : 2))
scenes=${*:-calm pool lake pool-map-scale godrays-pool godrays-lake godrays-ocean}
vkwater="$build/tools/vkwater/vkwater"
[ -x "$vkwater" ] || { echo "run.sh: $vkwater not found (build the vkwater target first)" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
source tools/benchmarks/provenance.sh

godrays='effects.godrays.mode=off|effects.godrays.grid=32|effects.godrays.grid=128'
caustics='effects.caustics.mode=off|effects.caustics.kernel=bilinear|effects.caustics.kernel=adaptive|effects.caustics.kernel=footprint|effects.caustics.method=procedural|effects.caustics.splat=camera-space'

godray_methods='effects.godrays.method=lines effects.godrays.grid=32|effects.godrays.method=lines effects.godrays.grid=64|effects.godrays.method=lines effects.godrays.grid=128|effects.godrays.method=lines effects.godrays.grid=256|effects.godrays.method=marched effects.godrays.march_steps=8|effects.godrays.method=marched effects.godrays.march_steps=16|effects.godrays.method=marched effects.godrays.march_steps=32|effects.godrays.method=marched effects.godrays.march_steps=64'

# Each CSV's first line says where its figures come from: the date, the commit, the device, the CPU
# count and the load average before and after its sweep (tools/benchmarks/provenance.sh); `vkwater
# bench merge` and the tests read past lines that begin with #.
bench_into() {  # output name, scene, then bench's sweep arguments
    local name=$1 scene=$2
    shift 2
    provenance_start
    "$vkwater" bench "scenes/$scene.json" --reference "tests/references/$scene.exr" --frames "$frames" \
        --out-dir "$scratch/$name" "$@"
    {
        echo "# $(provenance_line "$vkwater" "$frames timed frames per setting")"
        cat "$scratch/$name/sweep.csv"
    } >"docs/sweeps/$name.csv"
    cp "$scratch/$name/sweep.svg" "docs/sweeps/$name.svg"
}

sweep() {  # scene, then bench's sweep arguments
    bench_into "$1" "$@"
}

godray_sweep() {  # scene, its own water grid
    bench_into "godrays-$1" "$1" --grids "$2" --alternatives "$godray_methods" \
        --sweep effects.godrays.resolution_scale=0.5,1
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
        bench_into pool-map-scale pool --grids 256,512,1024 --sweep effects.caustics.map_scale=1,2,4 \
            --set effects.godrays.mode=off
        ;;
    godrays-pool) godray_sweep pool 1024 ;;
    godrays-lake) godray_sweep lake 512 ;;
    godrays-ocean) godray_sweep ocean 1024 ;;
    *)
        echo "run.sh: no sweep for '$scene' (accepted: calm, pool, lake, pool-map-scale, godrays-pool, godrays-lake," \
            "godrays-ocean)" >&2
        exit 1
        ;;
    esac
done
