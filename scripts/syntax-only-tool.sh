#!/usr/bin/env bash
# scripts/check-one-batch.sh's compiler launcher, archiver and linker launcher: a compile checks
# syntax and types only (-fsyntax-only), and an object, archive or program is an empty file, since
# nothing it makes is run.
set -euo pipefail
if [ "${1:-}" = qc ]; then : > "$2"; exit 0; fi  # as the archiver: ar qc ARCHIVE OBJECTS...
out=""
compile=0
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  case "${args[$i]}" in
    -o) out=${args[$((i + 1))]} ;;
    -c) compile=1 ;;
  esac
done
if [ "$compile" = 1 ]; then "$@" -fsyntax-only; fi
if [ -n "$out" ]; then : > "$out"; fi
