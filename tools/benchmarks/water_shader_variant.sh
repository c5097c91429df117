# Sourced by the benchmark scripts that time shader-only variants of the water's fragment shader
# (water_pass_parts.sh, uniform_mesh_march.sh), from the repository's root. Sets `vkwater` (the
# build's binary; it stops the script if the tree is not built) and `work` (a scratch directory,
# removed when the script exits). Defines:
#   water_variant NAME PYTHON_EDIT   build/shaders copied to $work/NAME with every variant of
#                                    water_surface.frag recompiled from a copy of shaders/ that
#                                    PYTHON_EDIT (Python, run with `root` the copy's path and the
#                                    helper `replace(path, old, new)`, which asserts that `old`
#                                    occurs once) has changed. VKWATER_SHADER_DIR=$work/NAME runs it.
vkwater=build/tools/vkwater/vkwater
[ -x "$vkwater" ] || { echo "build first: $vkwater is missing" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

water_variant() {
  local name=$1 edit=$2
  cp -r shaders "$work/src_$name"
  python3 -c "root = '$work/src_$name'
def replace(path, old, new):
    text = open(root + '/' + path).read()
    assert text.count(old) == 1, (path, old)
    open(root + '/' + path, 'w').write(text.replace(old, new))
$edit"
  cp -r build/shaders "$work/$name"
  grep -o "glslangValidator --quiet --target-env vulkan1.3 [^&]*water_surface.frag " build/build.ninja | sort -u |
    while read -r line; do
      read -r -a defines <<< "$(echo "$line" | grep -o -- "-DVKWATER_[A-Z_]*" | tr '\n' ' ')"
      out=$(echo "$line" | grep -o -- "-o [^ ]*" | awk '{print $2}' | sed "s#$PWD/build/shaders#$work/$name#")
      glslangValidator --quiet --target-env vulkan1.3 "${defines[@]}" -I"$work/src_$name" -o "$out" \
        "$work/src_$name/water/water_surface.frag"
    done
}
