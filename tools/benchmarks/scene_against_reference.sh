# Sourced by the scripts that render one scene against a reference (error_decomposition.sh,
# convergence.sh): their arguments SCENE REFERENCE [VKWATER] and a scratch folder removed on exit.
set -euo pipefail
scene=$1
reference=$2
vkwater=${3:-build/tools/vkwater/vkwater}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
