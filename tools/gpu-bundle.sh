#!/usr/bin/env bash
# gpu-bundle.sh pack OUT.tar.xz | gpu-bundle.sh run BUNDLE.tar.xz [CTEST ARGS...]
#
# Runs this tree's tests and tools on another x86-64 Linux machine that has a Vulkan driver but
# none of the build's dependencies (a GPU machine without Debian's packages, or without a
# network to fetch them).
#
# pack: bundles the built tree (build/: executables stripped, SPIR-V, the ctest files) with the
#   shared libraries its programs need beyond glibc and libstdc++, the glvnd libraries that
#   NVIDIA's Vulkan driver loads, and the Khronos validation layer with its manifest.
# run: from a checkout of the same commit on the other machine. Unpacks the bundle, puts the
#   build where ctest's files expect it (they hold the absolute path of the tree that built it),
#   points the loader at the bundled layer and at NVIDIA's driver manifest where it is, and
#   runs ctest without the tests that need what the bundle lacks: a virtual X server (window),
#   clang's sanitizer build, the soak test's Python, clang-format and POV-Ray.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
verb=${1:-}
bundle=${2:-}
[ -n "$verb" ] && [ -n "$bundle" ] || { echo "usage: tools/gpu-bundle.sh pack|run FILE.tar.xz [CTEST ARGS...]" >&2; exit 1; }
shift 2

if [ "$verb" = pack ]; then
  [ -x build/tools/vkwater/vkwater ] || { echo "gpu-bundle: build this tree first (build/)" >&2; exit 1; }
  stage=$(mktemp -d)
  trap 'rm -rf "$stage"' EXIT
  mkdir -p "$stage/lib" "$stage/layer"
  echo "$root" > "$stage/built-at"
  (cd build && find . \( -path ./sanitize -o -path '*/CMakeFiles' -o -path ./frame_ratio -o -path ./Testing \) -prune \
      -o -type f -print) | grep -vE '\.(o|a|d|log|exr|png|pov|ninja_log|ninja_deps|ninja)$' |
    while read -r file; do
      mkdir -p "$stage/build/$(dirname "$file")"
      cp -p "build/$file" "$stage/build/$file"
    done
  programs=$(find "$stage/build" -type f -executable -exec sh -c 'head -c 4 "$1" | grep -q ELF && echo "$1"' _ {} \;)
  strip $programs
  # (awk reads to the end: exiting early would kill ldconfig with SIGPIPE, which pipefail reports)
  layer=$(ldconfig -p | awk '/libVkLayer_khronos_validation.so / && !found {print $NF; found = 1}')
  [ -n "$layer" ] || { echo "gpu-bundle: the validation layer is not installed (tools/install-deps.sh)" >&2; exit 1; }
  for library in $(ldd $programs "$layer" | awk '/=>/ {print $3}' | sort -u); do
    case $(basename "$library") in
      libc.so* | libm.so* | libpthread.so* | libdl.so* | librt.so* | ld-linux* | libstdc++.so* | libgcc_s.so*) ;;
      *) cp -L "$library" "$stage/lib/" ;;
    esac
  done
  for library in libGLdispatch.so.0 libGLX.so.0 libGL.so.1 libEGL.so.1 libOpenGL.so.0; do
    path=$(ldconfig -p | awk -v name="$library" '$1 == name && !found {print $NF; found = 1}')
    [ -z "$path" ] || cp -L "$path" "$stage/lib/"
  done
  cp -L "$layer" "$stage/lib/"
  cp /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json "$stage/layer/"
  tar -C "$stage" -cf - . | xz -6 -T0 > "$bundle"
  echo "gpu-bundle: wrote $bundle ($(du -h "$bundle" | cut -f1))"
  exit 0
fi

[ "$verb" = run ] || { echo "gpu-bundle: unknown verb '$verb' (pack or run)" >&2; exit 1; }
unpacked=${GPU_BUNDLE_DIR:-/tmp/vkwater-gpu-bundle}
rm -rf "$unpacked" && mkdir -p "$unpacked"
# Python's tarfile reads .xz where the xz program may be missing.
python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$bundle" "$unpacked"
built_at=$(cat "$unpacked/built-at")
[ -e "$root/build" ] || ln -s "$unpacked/build" "$root/build"
if [ "$built_at" != "$root" ]; then
  [ ! -e "$built_at" ] || { echo "gpu-bundle: $built_at exists; run from there, or remove it" >&2; exit 1; }
  mkdir -p "$(dirname "$built_at")" && ln -s "$root" "$built_at"
fi
export LD_LIBRARY_PATH="$unpacked/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" VK_LAYER_PATH="$unpacked/layer"
nvidia_manifest=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
[ ! -f "$nvidia_manifest" ] || export VK_DRIVER_FILES="$nvidia_manifest" VK_ICD_FILENAMES="$nvidia_manifest"
cd "$built_at"
ctest --test-dir build -j"$(nproc)" --timeout 300 -LE 'sanitize|soak|window|source_tree' -E '^fuzz|povray' \
  --output-on-failure "$@"
