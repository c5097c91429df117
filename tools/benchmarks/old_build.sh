# Sourced by the scripts that time this tree against an older commit (frame_ratio.sh,
# equal_time.sh). Reads their arguments OLD_COMMIT [ROUNDS] [SCENE ...] (USAGE names the script
# for the error) and sets old_commit, rounds, scenes (empty: the script's own list), new_vk and
# old_vk: OLD_BUILD=DIR's binary, or OLD_COMMIT built beside this tree in
# build/frame_ratio/OLD_COMMIT (a git worktree and a release build of the vkwater target).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)

if [ $# -lt 1 ]; then
  echo "usage: $USAGE OLD_COMMIT [ROUNDS] [SCENE ...]" >&2
  exit 1
fi
old_commit=$(git rev-parse --short "$1")
rounds=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
scenes=("$@")

new_vk=$root/build/tools/vkwater/vkwater
[ -x "$new_vk" ] || { echo "$USAGE: build this tree first (build/tools/vkwater/vkwater)" >&2; exit 1; }

old_build=${OLD_BUILD:-$root/build/frame_ratio/$old_commit}
old_vk=$old_build/tools/vkwater/vkwater
if [ ! -x "$old_vk" ]; then
  source_dir=$root/build/frame_ratio/$old_commit-src
  [ -d "$source_dir" ] || git worktree add --detach "$source_dir" "$old_commit" > /dev/null
  cmake -S "$source_dir" -B "$old_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF > /dev/null
  cmake --build "$old_build" --target vkwater > /dev/null
fi
