#!/usr/bin/env bash
# run.sh SOURCE_DIR BUILD_DIR: builds the loaders (scene, --set, glTF, EXR), `vkwater check` and
# `vkwater compare` with clang, AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer
# (VKWATER_LOADERS_ONLY: no Vulkan, so no driver's own reports to suppress), then runs their unit
# tests, the malformed-input corpus and each libFuzzer target under them. Any sanitizer report
# fails the run.
set -euo pipefail
source_dir=$1 build_dir=$2
here=$(cd "$(dirname "$0")" && pwd)
cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DVKWATER_LOADERS_ONLY=ON -DVKWATER_SANITIZE=ON -DVKWATER_FUZZ=ON >/dev/null
cmake --build "$build_dir"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:suppressions=$here/asan.supp"
export LSAN_OPTIONS="suppressions=$here/lsan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$here/ubsan.supp"
ctest --test-dir "$build_dir" -j2 --output-on-failure
