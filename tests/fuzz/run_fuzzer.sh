#!/usr/bin/env bash
# run_fuzzer.sh FUZZER SECONDS FOUND_DIR DICT SEED_DIR...: fuzzes for SECONDS from the seeds, new
# inputs into FOUND_DIR (created). libFuzzer exits non-zero on a crash, a sanitizer report, an
# uncaught exception or an input that runs longer than 60 s, and leaves the input as crash-* or
# timeout-* here. 60 s, because the largest valid inputs are slow under ASan: a terrain receiver
# at its limit of 2048 cells a side (4.2 M vertices) took more than 10 s to build.
# For a longer run: run_fuzzer.sh build/sanitize/tests/fuzz/fuzz_scene 3600 /tmp/found tests/fuzz/scene.dict scenes
set -euo pipefail
fuzzer=$1 seconds=$2 found=$3 dict=$4
shift 4
mkdir -p "$found"
exec "$fuzzer" -max_total_time="$seconds" -timeout=60 -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
  -dict="$dict" "$found" "$@"
