#!/usr/bin/env bash
# second_layer_parts.sh [ROUNDS]
#
# Where the water pass's extra time with the refraction view's second layer goes, on lake at
# 800x600 (docs/performance-log.md, "The refraction view's second layer"). Shader-only variants of the
# water's fragment shader (water_shader_variant.sh), each with the layer drawn, against the layer
# off (`--set effects.refraction_second_layer.mode=off`, the shader as built):
#   - as built: the retried rays marched through the peeled view;
#   - no march: the rays that would be retried keep the first layer's answer, the march's code
#     left out;
#   - march never taken: the march's code kept, behind a test that no pixel passes at run time
#     (the camera's x below -1000 m), so llvmpipe compiles it but no lane runs it.
# The variants change the picture (the last two are the layer-off image); only their times are
# read. ROUNDS interleaved rounds (default 5), medians. Prints a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/../.."
source "$(dirname "$0")/provenance.sh"
provenance_start
rounds=${1:-5}
source "$(dirname "$0")/water_shader_variant.sh"

march='    SceneHit peeled_hit;
    if (!screen_space_lookup(refraction_view, true,'
water_variant as_built ""
water_variant no_march "
replace('water/scene_lookup.glsl', '''$march''', '''    return found;
$march''')"
water_variant march_never_taken "
replace('water/scene_lookup.glsl', '''$march''', '''    if (frame.camera_position.x > -1000.0) return found;
$march''')"

configurations=("as_built|" "no_march|" "march_never_taken|" "layer_off|--set effects.refraction_second_layer.mode=off")
for round in $(seq "$rounds"); do
  for k in $(seq 0 $((${#configurations[@]} - 1))); do
    i=$(((k + round - 1) % ${#configurations[@]}))
    IFS='|' read -r name options <<< "${configurations[$i]}"
    read -r -a args <<< "$options"
    shaders=$work/${name/layer_off/as_built}
    VKWATER_SHADER_DIR="$shaders" "$vkwater" render scenes/lake.json --width 800 --height 600 --repeat 2 "${args[@]}" \
      --out "$work/image.exr" 2>&1 | awk -v n="$name" '$1 == "water" && $3 == "ms" { print n, "water", $2 }
        $1 == "refraction" && $3 == "second" { print n, "layer", $5 }
        $1 == "frame" { print n, "frame", $2 }
        $1 == "calibration" { print n, "calibration", $2 }'
  done
done > "$work/times"

provenance_line "$vkwater" "lake at 800x600, medians of $rounds interleaved rounds"
echo "| lake, 800x600 | water pass, ms | second layer's pass, ms | frame, ms | water / layer off |"
echo "| --- | --- | --- | --- | --- |"
python3 - "$work/times" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
def median(name, part):
    times = [float(t) for n, p, t in rows if n == name and p == part]
    return statistics.median(times) if times else None
off = median("layer_off", "water")
for name in ("as_built", "no_march", "march_never_taken", "layer_off"):
    water, layer, frame = median(name, "water"), median(name, "layer"), median(name, "frame")
    layer_text = f"{layer:.1f}" if layer is not None else "-"
    print(f"| {name.replace('_', ' ')} | {water:.1f} | {layer_text} | {frame:.1f} | {water / off:.2f} |")
PY
