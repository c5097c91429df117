#!/usr/bin/env bash
# Installs every Debian package that vkwater's build, tests and tools use.
# Idempotent: re-running it only re-checks the packages. Nothing is downloaded
# outside Debian's archive, and nothing is vendored into the source tree.
set -euo pipefail

packages=(
  # build
  build-essential cmake pkg-config ninja-build
  # the committed C++ format (.clang-format; tools/check-format.sh, a test): version 14 exactly
  clang-format-14
  # Vulkan: loader + headers, the software driver (lavapipe), tools, validation layers
  libvulkan-dev mesa-vulkan-drivers vulkan-tools vulkan-validationlayers
  # shader compilers and SPIR-V tools
  glslang-tools glslc spirv-tools
  # SPIR-V reflection of every pipeline's shaders against its layout (engine/vk/spirv_reflection.cpp)
  libspirv-cross-c-shared-dev
  # libraries
  libglm-dev libglfw3-dev libtinygltf-dev libopenexr-dev nlohmann-json3-dev libcli11-dev
  libimgui-dev libstb-dev libgtest-dev
  # libpng: the PNG preview's encoder; zlib: the PNG test checks the sRGB chunk's CRC
  libpng-dev zlib1g-dev
  # EXR inspection and conversion (exrheader, oiiotool)
  openexr openimageio-tools
  # window tests and screenshots; xdotool types and clicks in the viewer's window (tests/view)
  xvfb xauth x11-apps imagemagick xdotool
  # the independent cross-check of the reference's floor caustics (tests/povray)
  povray
  # Khronos glTF 2.0 sample models that the rendering tests load (tests/render/khronos_samples_test.cpp)
  assimp-testmodels
  # the corpus generator and the viewer's soak test (tests/corpus, tests/soak)
  python3
  # the sanitizer and fuzzing build of the loaders (tests/sanitize, tests/fuzz): clang with its
  # AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer runtimes
  clang-14 libclang-rt-14-dev
  # the frame graph diagram in docs/architecture.md (docs/images/frame_graph.sh, a test)
  graphviz
  # the peer demo's browser (tools/benchmarks/peer_demo.sh): WebGL in headless Chromium on the
  # SwiftShader it ships, the CPU device a peer's web demo meets on this machine
  chromium
  # the bundle that carries the build to a machine without these packages (tools/gpu-bundle.sh)
  xz-utils
  # the batch scheduler test (tests/slurm): a single-node Slurm started in a temporary folder
  # (tools/slurm/local_cluster.sh), its own munged included
  slurm-wlm munge
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null

# The packages' own munge, slurmctld and slurmd services: installing starts them where the init
# system lets it, but tests/slurm starts its own daemons and nothing should run in the background.
# Without systemd, each is disabled (`update-rc.d disable` keeps its stop links through upgrades,
# where removed links would be put back) and stopped by its pid file alone: the Debian init scripts
# of slurmd and slurmctld stop every process of that program, a test's local cluster too. A service
# that is missing or not running is fine.
stop_service() {  # NAME PIDFILE
  if [ -d /run/systemd/system ]; then  # systemd is the running init
    "${sudo_cmd[@]}" systemctl disable --now "$1" >/dev/null 2>&1 || true
  elif [ -x "/etc/init.d/$1" ]; then
    "${sudo_cmd[@]}" update-rc.d "$1" disable >/dev/null 2>&1 || true
    "${sudo_cmd[@]}" start-stop-daemon --stop --quiet --oknodo --retry 10 --pidfile "$2" >/dev/null 2>&1 || true
  fi
}
stop_service slurmd /run/slurmd.pid
stop_service slurmctld /run/slurmctld.pid
stop_service munge /run/munge/munged.pid
echo "install-deps: ${#packages[@]} packages present"
