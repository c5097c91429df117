#!/usr/bin/env bash
# tools/benchmarks/budget_error_terms.sh [SCENE...]: the error table of the frame-time budget
# (tools/vkwater/budget/error_model.hpp). For each scene (default: pool, lake, ocean and box, against
# their box-filtered references in tests/references/box/, and the two showcase scenes against their
# point-sampled ones in tests/references/showcase/; box for its scene lookups, whose loss is the
# largest there: a red box reflected against a sky without red, seen over a black floor), renders it at 400x300 with one quality
# knob changed at a time from the scene's own settings, and prints one CSV row per render: the
# knob, its value, the relMSE against the scene's box reference, and the excess over the
# scene's own settings. The knobs and their values are the budget's candidates
# (tools/vkwater/budget/quality.hpp): the resolution scale (and, as render_scale 2, the scene
# rendered at 800x600 and box-averaged to 400x300, whose signed excess is the gain of twice the
# rows, for the error model's resolution term); where the scene has a box reference, 4, 9 and 16
# samples per pixel (signed gains too: k^2 samples are k times the rows); the photon grid as a fraction of the
# scene's; the water mesh's cells per side; the godray grid (0: godrays off); where the water
# looks the scene up (`vkwater passes` says reflection or refraction: on), the lookups' steps and
# each lookup turned off; and,
# where photons are splatted into the light-space map (`caustic photons` among the passes), the
# bilinear kernel in place of the scene's (the value: the photon grid fraction it is measured at,
# the excess over the scene's kernel at that grid) and the map's scale as a fraction of the
# scene's; where the needs run the refraction view's second layer, the layer off; where receiver
# meshes cast into the sun shadow map, its texels per side at 512 and 256; where the scene has
# terrain receivers, their cells per side at half and a quarter of their own. Writes
# docs/sweeps/budget_error_terms.csv, under a first line that says where it comes from. About 12 min
# on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/../.."
vk=${VKWATER:-build/tools/vkwater/vkwater}
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(pool lake ocean box showcase/pool showcase/lagoon)
csv=docs/sweeps/budget_error_terms.csv
source tools/benchmarks/provenance.sh
source tools/benchmarks/box_averaged.sh
provenance_start
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

reference() {  # SCENE: its box-filtered reference where there is one, else its point-sampled one
    if [ -f "tests/references/box/$1.exr" ]; then echo "tests/references/box/$1.exr"; else echo "tests/references/$1.exr"; fi
}

relmse() {  # SCENE ARGS...: the relMSE of one render against the scene's reference
    local scene=$1
    shift
    "$vk" render "scenes/$scene.json" --width 400 --height 300 --out "$out/frame.exr" \
        --reference "$(reference "$scene")" "$@" 2>/dev/null | awk '/^error against/ {print $5; exit}' |
        tr -d ,
}

# The same at twice the size (800x600), box-averaged down to 400x300 before the comparison: the
# error of rendering twice the reference's rows (render_scale 2 below).
relmse_twice() {  # SCENE
    box_averaged_relmse "$vk" "scenes/$1.json" "$(reference "$1")" 800 600 "$out"
}

echo "scene,knob,value,rel_mse,excess" >"$out/rows.csv"
for scene in "${scenes[@]}"; do
    # The scene's own settings: its photon grid, the mesh it draws, its godray grid.
    read -r grid mesh godrays kernel map_scale < <(python3 - "scenes/$scene.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
water = scene.get("water", {})
grid = water.get("grid_resolution", 256)
# Infinite water is drawn from the screen's grid: no uniform mesh to turn (0).
mesh = 0 if water.get("half_extent") == "infinite" else water.get("mesh_resolution", min(256, grid))
effects = scene.get("effects", {})
godrays = effects.get("godrays", {}).get("grid", 64)
caustics = effects.get("caustics", {})
print(grid, mesh, godrays, caustics.get("kernel", "adaptive"), caustics.get("map_scale", 1.0))
PY
    )
    base=$(relmse "$scene")
    # KNOB VALUE RELMSE [AGAINST] [signed]: the excess over AGAINST (default the scene's own
    # settings' relMSE), at least 0 unless signed (twice the rows: a gain, which the resolution term
    # needs).
    row() {
        [ -n "$3" ] || { echo "budget_error_terms.sh: $scene, $1 = $2 gave no relMSE (the render failed)" >&2; exit 1; }
        local against=${4:-$base} floor=0.0
        [ "${5:-}" != signed ] || floor=-1.0
        echo "$scene,$1,$2,$3,$(python3 -c "print(f'{max($floor, $3 - $against):.6g}')")" >>"$out/rows.csv"
    }
    needs=$("$vk" passes "scenes/$scene.json" --width 400 --height 300)
    # The bilinear kernel's rows: where photons are splatted into the light-space map with another
    # kernel, at each photon grid, against the scene's kernel at that grid (its excess grows as the
    # grid coarsens, so one figure at the scene's grid would understate it).
    photon_map=false bilinear_rows=false
    if grep -qE '^ +[0-9]+\. caustic photons ' <<<"$needs"; then photon_map=true; fi
    if $photon_map && [ "$kernel" != bilinear ]; then bilinear_rows=true; fi
    row render_scale 2 "$(relmse_twice "$scene")" "$base" signed
    for scale in 1 0.75 0.5 0.35 0.25; do
        row render_scale "$scale" "$(relmse "$scene" --render-scale "$scale")"
    done
    # k^2 samples per pixel sample the pixel as k times the rows would (the strata's centres are a
    # k-times finer image's pixel centres): signed gains, against the box reference only (a
    # point-sampled one would count the filter as error).
    if [ -f "tests/references/box/$scene.exr" ]; then
        for spp in 4 9 16; do
            row samples_per_pixel "$spp" "$(relmse "$scene" --spp "$spp")" "$base" signed
        done
    fi
    for fraction in 1 0.5 0.25 0.125; do
        g=$(python3 -c "print(max(2, round($grid * $fraction)))")
        m=$((mesh < g ? mesh : g))
        mesh_option=()
        [ "$mesh" = 0 ] || mesh_option=(--set "water.mesh_resolution=$m")
        at_grid=$(relmse "$scene" --set "water.grid_resolution=$g" "${mesh_option[@]}")
        row photon_grid_fraction "$fraction" "$at_grid"
        if $bilinear_rows; then
            row bilinear_kernel "$fraction" "$(relmse "$scene" --set "water.grid_resolution=$g" "${mesh_option[@]}" \
                --set effects.caustics.kernel=bilinear)" "$at_grid"
        fi
    done
    for m in 256 128 64; do
        [ "$mesh" != 0 ] && [ "$m" -le "$mesh" ] || continue
        row mesh_resolution "$m" "$(relmse "$scene" --set "water.mesh_resolution=$m")"
    done
    if grep -qE '^  (reflection|refraction): on' <<<"$needs"; then
        for steps in 16 8; do
            row lookup_steps "$steps" "$(relmse "$scene" --set "effects.reflection.max_steps=$steps" \
                --set "effects.refraction.max_steps=$steps")"
        done
    fi
    # Each lookup turned off alone (value 0), where the needs run it: its rays keep the exact floor
    # and sky and miss the receiver meshes.
    for lookup in reflection refraction; do
        if grep -qE "^  $lookup: on" <<<"$needs"; then
            row "${lookup}_lookup" 0 "$(relmse "$scene" --set "effects.$lookup.mode=off")"
        fi
    done
    if $photon_map; then
        half_map=$(python3 -c "print(max(0.25, $map_scale * 0.5))")
        row map_scale_fraction 0.5 "$(relmse "$scene" --set "effects.caustics.map_scale=$half_map")"
    fi
    # The sun shadow map's texels per side, where receiver meshes cast into it.
    if grep -qE '^ +[0-9]+\. sun shadow map ' <<<"$needs"; then
        for texels in 512 256; do
            row shadow_texels "$texels" "$(relmse "$scene" --set "sun.shadow_texels=$texels")"
        done
    fi
    # The terrain receivers' cells per side as a fraction of each one's own (at least 2), where the
    # scene has terrain: every terrain receiver at once, as the budget turns them.
    for fraction in 0.5 0.25; do
        terrain=()
        while read -r option; do terrain+=(--set "$option"); done < <(python3 - "scenes/$scene.json" "$fraction" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
for i, receiver in enumerate(scene.get("receivers", [])):
    if receiver.get("type") == "terrain":
        # Rounded half up, as terrain_cells (engine/scene/scene.hpp) rounds: Python's round() goes to even.
        print(f"receivers[{i}].resolution={max(2, int(receiver.get('resolution', 64) * float(sys.argv[2]) + 0.5))}")
PY
        )
        [ ${#terrain[@]} -gt 0 ] || break
        row terrain_fraction "$fraction" "$(relmse "$scene" "${terrain[@]}")"
    done
    # The refraction view's second layer, where the needs run it: turned off (value 0).
    if grep -qE '^  refraction_second_layer: on' <<<"$needs"; then
        row second_layer 0 "$(relmse "$scene" --set effects.refraction_second_layer.mode=off)"
    fi
    for g in 64 32 16 0; do
        [ "$g" -le "$godrays" ] || continue
        if [ "$g" = 0 ]; then
            row godray_grid 0 "$(relmse "$scene" --set effects.godrays.mode=off)"
        else
            row godray_grid "$g" "$(relmse "$scene" --set "effects.godrays.grid=$g")"
        fi
    done
done
# The file's first line says where its figures come from (the readers skip lines that begin with #);
# made before the tracked file is rewritten, so that it names the tree as it was measured.
line=$(provenance_line "$vk" "errors only, which the machine's load does not change")
{
    echo "# $line"
    cat "$out/rows.csv"
} >"$csv"
cat "$csv"
