#!/usr/bin/env bash
# Installs the Debian 12 packages radmesh builds and tests with; does nothing for those already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config ca-certificates
  libglfw3-dev libosmesa6-dev libglm-dev libimgui-dev libtinygltf-dev libstb-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev
  python3-glad xvfb xauth gnuplot-nox
  libopenmpi-dev openmpi-bin
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing: ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
