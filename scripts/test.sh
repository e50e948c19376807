#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite twice: the Release build, then
# the same tests under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)

build_and_test() {  # folder, then extra CMake options
  local dir=$1; shift
  echo "== $dir: configure and build"
  cmake -S . -B "$dir" "$@" > "$dir.log" 2>&1 || { cat "$dir.log"; exit 1; }
  cmake --build "$dir" -j"$jobs" >> "$dir.log" 2>&1 || { tail -80 "$dir.log"; exit 1; }
  echo "== $dir: tests"
  ctest --test-dir "$dir" -j"$jobs" --output-on-failure --timeout 600
}

mkdir -p build
build_and_test build -DCMAKE_BUILD_TYPE=Release
# Sanitizers: leak checks off because Mesa's llvmpipe keeps its JIT caches until exit.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
build_and_test build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRADMESH_SANITIZE=ON -DRADMESH_BUILD_BENCHMARKS=OFF
