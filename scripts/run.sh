#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on the built-in office: the walkthrough
# window when there is a display; otherwise a solve in the terminal with a bake and a picture.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j"$(nproc)" >> build.log 2>&1 || { tail -50 build.log; exit 1; }

scene=${1:-office}
if [ -n "${DISPLAY:-}" ] && [ -x build/viewer/radmesh-view ]; then
  exec build/viewer/radmesh-view "$scene"
fi
mkdir -p out
name=$(basename "${scene%.*}")  # a built-in name, or a file's stem
echo "radmesh: no display, so solving $scene here; the bake and a picture go to out/"
build/cli/radmesh solve "$scene" --stats "out/$name-stats.json" --out "out/$name.glb"
# The picture is drawn from the bake just written (through OSMesa: no display needed).
build/cli/radmesh render "out/$name.glb" --out "out/$name.png"
