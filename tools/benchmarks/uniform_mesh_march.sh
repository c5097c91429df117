#!/usr/bin/env bash
# uniform_mesh_march.sh [ROUNDS]
#
# Whether pool's uniform water mesh could be coarser if each pixel marched for the first crossing
# where its refinement window is long (the screen's grid does; the uniform mesh compiles the march
# out, water/surface_refinement.glsl). Two shader-only builds of the water's fragment shader:
#   as built  shaders/ unchanged: Newton from the window's front, then from the mesh point;
#   march     the screen grid's march for the first change of side also on the uniform mesh,
#             where the window runs longer than 4 march steps (the far field's grazing rays).
# First the error against the committed point reference at 400x300 (tests/references/pool.exr,
# whole image and caustic layer) at mesh resolutions 256 (pool's default), 128, 96 and 64; then the
# water pass at 400x300 and 800x600, interleaved, the median of ROUNDS (default 5) rounds, in
# calibration passes of the same frame. Prints two Markdown tables (docs/performance-log.md, "A coarser
# uniform mesh with the march").
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
rounds=${1:-5}
source "$(dirname "$0")/water_shader_variant.sh"
water_variant as_built ""
water_variant march "
replace('water/surface_refinement.glsl',
        'const bool can_march = WATER_SCREEN_GRID != 0u && params.march_step > 0.0 && march_hi > march_lo;',
        'const bool can_march = params.march_step > 0.0 && march_hi > march_lo;')"

echo "| pool, 400x300, mesh | relMSE, as built | relMSE, march | caustic relMSE, as built | caustic relMSE, march |"
echo "| --- | --- | --- | --- | --- |"
for mesh in 256 128 96 64; do
  row="| $mesh"
  for name in as_built march; do
    VKWATER_SHADER_DIR="$work/$name" "$vkwater" render scenes/pool.json --width 400 --height 300 \
      --set water.mesh_resolution=$mesh --reference tests/references/pool.exr --out "$work/image.exr" 2>&1 |
      sed -n 's/.*: relMSE \([0-9.e-]*\),.*caustic relMSE \([0-9.e-]*\),.*/\1 \2/p' > "$work/error_$name"
  done
  read -r image_built caustic_built < "$work/error_as_built"
  read -r image_march caustic_march < "$work/error_march"
  echo "$row | $image_built | $image_march | $caustic_built | $caustic_march |"
done
echo

settings=("as_built 256" "as_built 128" "march 128" "march 96")
for round in $(seq "$rounds"); do
  for size in 400x300 800x600; do
    for setting in "${settings[@]}"; do
      read -r name mesh <<< "$setting"
      VKWATER_SHADER_DIR="$work/$name" "$vkwater" render scenes/pool.json --width "${size%x*}" --height "${size#*x}" \
        --repeat 2 --set water.mesh_resolution=$mesh --out "$work/image.exr" 2>&1 |
        awk -v s="$size $name $mesh" '$1 == "water" && $3 == "ms" { print s, "water", $2 }
                                      $1 == "calibration" { print s, "calibration", $2 }'
    done
  done
done > "$work/times"

provenance_line "$vkwater" "$rounds interleaved rounds"
echo "| pool | water pass, ms | water / calibration | water / as built at 256 |"
echo "| --- | --- | --- | --- |"
python3 - "$work/times" "${settings[@]}" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
def median(size, name, mesh, part):
    return statistics.median(float(r[4]) for r in rows if r[:4] == [size, name, mesh, part])
for size in ("400x300", "800x600"):
    base = median(size, "as_built", "256", "water")
    for setting in sys.argv[2:]:
        name, mesh = setting.split()
        water = median(size, name, mesh, "water")
        cal = median(size, name, mesh, "calibration")
        print(f"| {size}, {name.replace('_', ' ')}, mesh {mesh} | {water:.1f} | {water / cal:.0f} | {water / base:.2f} |")
PY
