#!/usr/bin/env bash
# Regenerates the figures of docs/paper-reproduction.md from a Release build in build/.
# Usage: bash docs/reproduce-paper.sh [SCENE]   (default: the built-in office)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-office}
name=$(basename "${scene%.*}")
out=docs/data
mkdir -p "$out" docs/images
for n in 64 128 256; do
  build/cli/radmesh solve "$scene" --backend mesh --resolution "$n" --until 0.95 --quiet \
    --stats "$out/paper-$name-mesh-$n.json"
done
# Table 1.3: form-factor reuse as convergence climbs (native backend, the same shooting order).
build/cli/radmesh solve "$scene" --resolution 128 --until 0.9965 --max-iterations 5000 --quiet \
  --stats "$out/paper-$name-reuse.json"
python3 docs/paper_figures.py "$name" "$out" docs/images
