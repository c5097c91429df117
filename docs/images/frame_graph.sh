#!/usr/bin/env bash
# docs/images/frame_graph.sh [BUILD_DIR] [--check]: the frame graph of the Quick start's scene
# (scenes/showcase/pool.json) as `vkwater passes --dot` writes it (docs/images/frame_graph.dot)
# and as Graphviz draws it (docs/images/frame_graph.svg), for docs/architecture.md.
# With --check it writes nothing and fails when either committed file differs from what the
# current build makes (the ctest docs.FrameGraphDiagramIsCurrent).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=build
check=false
for arg in "$@"; do
  if [ "$arg" = --check ]; then check=true; else build=$arg; fi
done
vk=$build/tools/vkwater/vkwater
[ -x "$vk" ] || { echo "frame_graph.sh: build first ($vk)" >&2; exit 1; }
command -v dot > /dev/null || { echo "frame_graph.sh: Graphviz's dot is missing (tools/install-deps.sh installs it)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$vk" passes scenes/showcase/pool.json --dot "$work/frame_graph.dot" > /dev/null
dot -Tsvg "$work/frame_graph.dot" -o "$work/frame_graph.svg"
if $check; then
  status=0
  for file in frame_graph.dot frame_graph.svg; do
    if ! cmp -s "$work/$file" "docs/images/$file"; then
      echo "frame_graph.sh: docs/images/$file is not what this build makes; run docs/images/frame_graph.sh" >&2
      status=1
    fi
  done
  exit "$status"
fi
cp "$work/frame_graph.dot" "$work/frame_graph.svg" docs/images/
echo "wrote docs/images/frame_graph.dot and docs/images/frame_graph.svg"
