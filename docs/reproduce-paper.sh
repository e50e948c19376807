#!/usr/bin/env bash
# Regenerates the tables and figures of docs/paper-reproduction.md from a Release build in build/.
# Usage: bash docs/reproduce-paper.sh [SCENE [NAME [FIGURE_UNTIL]]]   (default: the built-in
# office; NAME names the output files, by default the scene file's base name; FIGURE_UNTIL is the
# convergence Figures 1.3 and 1.4 run to, by default the paper's 0.95)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-office}
name=${2:-$(basename "${scene%.*}")}
figure_until=${3:-0.95}
out=out/data  # the solves' stats JSON, not committed; the figures' CSV and PNGs go to docs/
mkdir -p "$out"
# Tables 1.1, 1.2 and the mapping comparison average the iterations to C = 0.95; Figures 1.3 and
# 1.4 follow the hierarchical runs to FIGURE_UNTIL (the same shots first: the solve is deterministic).
for mapping in hierarchical cut-and-stack adaptive; do
  until=0.95
  [ "$mapping" = hierarchical ] && until=$figure_until
  for n in 64 128 256; do
    build/cli/radmesh solve "$scene" --preset paper --backend mesh --mapping "$mapping" --resolution "$n" --until "$until" \
      --max-iterations 5000 --quiet --stats "$out/paper-$name-$mapping-$n.json"
  done
done
# Table 1.3: form-factor reuse as convergence climbs (native backend, the same shooting order).
build/cli/radmesh solve "$scene" --preset paper --resolution 128 --until 0.9965 --max-iterations 5000 --quiet \
  --stats "$out/paper-$name-reuse.json"
build/cli/radmesh plot paper "$name" --stats "$out" --csv "docs/data/paper-$name.csv" --images docs/images
