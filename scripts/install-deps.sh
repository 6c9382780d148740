#!/usr/bin/env bash
# Installs the Debian 12 packages Antumbra builds and tests with. Idempotent: does
# nothing when everything is present. Uses sudo when not root.
set -euo pipefail
packages=(
  build-essential cmake pkg-config clang clang-tidy clang-format python3 git
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-dev glslang-tools spirv-tools
  libglm-dev libtinygltf-dev nlohmann-json3-dev libspdlog-dev libstb-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev libglfw3-dev libimgui-dev
  xvfb xauth xdotool ccache
  assimp-testmodels renderdoc
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
