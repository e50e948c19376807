#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite: the Release build; the viewer's
# threaded tests (the solver thread against the UI's reads) under ThreadSanitizer; then every test
# again under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)

configure_and_build() {  # folder, target ("all" for everything), then extra CMake options
  local dir=$1 target=$2; shift 2
  echo "== $dir: configure and build"
  cmake -S . -B "$dir" "$@" > "$dir.log" 2>&1 || { cat "$dir.log"; exit 1; }
  cmake --build "$dir" -j"$jobs" --target "$target" >> "$dir.log" 2>&1 || { tail -80 "$dir.log"; exit 1; }
}

run_ctest() {
  echo "== $1: tests"
  ctest --test-dir "$1" -j"$jobs" --output-on-failure --timeout 600
}

configure_and_build build all -DCMAKE_BUILD_TYPE=Release
run_ctest build

# ThreadSanitizer: the programs whose tests run threads against each other: the viewer's solver
# thread against the UI's reads, and the host thread pool (alone and under the emulator).
configure_and_build build-tsan viewer_tests -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRADMESH_TSAN=ON -DRADMESH_BUILD_BENCHMARKS=OFF
cmake --build build-tsan -j"$jobs" --target parallel_tests emulator_tests >> build-tsan.log 2>&1 || { tail -80 build-tsan.log; exit 1; }
echo "== build-tsan: threaded viewer tests, the thread pool"
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
build-tsan/tests/viewer_tests --gtest_filter='SolverThread.*:Streaming.*'
build-tsan/tests/parallel_tests
build-tsan/tests/emulator_tests --gtest_filter='Determinism.*'

# Leak checks off because Mesa's llvmpipe keeps its JIT caches until exit.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# -O1 -g1, as the sanitizers' docs suggest: 8 min to build here instead of 12 with -O2 -g, the same line numbers in reports.
# The Release run's test times let ctest start the slowest sanitizer tests first (the long ones
# otherwise start last and leave a core idle).
mkdir -p build-asan/Testing/Temporary
cp build/Testing/Temporary/CTestCostData.txt build-asan/Testing/Temporary/
configure_and_build build-asan all -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DRADMESH_SANITIZE=ON -DRADMESH_BUILD_BENCHMARKS=OFF
run_ctest build-asan
