#!/usr/bin/env bash
# Compiles every target as a single unity batch, syntax only. In the unity build two files of a
# target share an anonymous namespace when they land in one batch, and which files do shifts as
# files are added: a name both define then stops the build far from the change that caused it.
# Here every pair of a target's files meets, so such a name is found when it is written.
# Usage: scripts/check-one-batch.sh [BUILD_DIR]   (default build-one-batch)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-one-batch}
tool=$PWD/scripts/syntax-only-tool.sh
generator=()
[ -f "$dir/CMakeCache.txt" ] || generator=(-G Ninja)
cmake -S . -B "$dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DRADMESH_UNITY=ON -DRADMESH_UNITY_BATCH=0 \
  -DCMAKE_C_COMPILER_LAUNCHER="$tool" -DCMAKE_CXX_COMPILER_LAUNCHER="$tool" -DCMAKE_CXX_LINKER_LAUNCHER="$tool" \
  -DCMAKE_AR="$tool" -DCMAKE_RANLIB=true > "$dir.log" 2>&1 || { cat "$dir.log"; exit 1; }
cmake --build "$dir" -j"$(nproc)" -- -k 0 >> "$dir.log" 2>&1 || { grep -E "error|FAILED" "$dir.log" | head -60; exit 1; }
echo "every target compiles as one batch"
