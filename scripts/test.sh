#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite under AddressSanitizer +
# UndefinedBehaviorSanitizer (benchmarks built too, so that they keep compiling); then the tests
# that run threads against each other (the viewer's solver thread against the UI's reads, the
# thread pool) under ThreadSanitizer. The suite runs once, under the sanitizers, rather than again
# in a Release build: two builds of everything do not fit CI's 30 minutes on 2 cores
# (scripts/run.sh makes the Release build a user runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc)
# Each phase's wall and CPU time, so that the CI log shows where the time goes.
TIMEFORMAT='   %0R s elapsed, %0U s user + %0S s system'

# Ninja starts a target's compiles without waiting for the libraries it links (a folder already
# configured keeps its generator).
configure_and_build() {  # folder, targets ("all" for everything), then extra CMake options
  local dir=$1 target=$2; shift 2
  echo "== $dir: configure and build"
  local generator=()
  [ -f "$dir/CMakeCache.txt" ] || generator=(-G Ninja)
  cmake -S . -B "$dir" "${generator[@]}" "$@" > "$dir.log" 2>&1 || { cat "$dir.log"; exit 1; }
  # shellcheck disable=SC2086  # the targets are words
  cmake --build "$dir" -j"$jobs" --target $target >> "$dir.log" 2>&1 || { tail -80 "$dir.log"; exit 1; }
}

run_ctest() {
  echo "== $1: tests"
  ctest --test-dir "$1" -j"$jobs" --output-on-failure --timeout 600
}

# First, as it takes about a minute: a name two files of a target both define breaks the unity build
# only when a batch puts them together; here every pair meets.
echo "== build-one-batch: every target as one unity batch, syntax only"
time bash scripts/check-one-batch.sh build-one-batch

# Leak checks off because Mesa's llvmpipe keeps its JIT caches until exit. A 64 MB quarantine of
# freed memory rather than 256: each test process faulted in fresh pages for all of it, about a
# quarter of the suite's system time (CI: 406 s of it before, 293-305 s after).
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:quarantine_size_mb=64 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# -O1 -g1, as the sanitizers' docs suggest: a third less to build than -O2 -g, the same line numbers in reports.
time configure_and_build build-asan all -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DRADMESH_SANITIZE=ON
time run_ctest build-asan

# ThreadSanitizer: the programs whose tests run threads against each other: the viewer's solver
# thread against the UI's reads, and the host thread pool (alone and under the emulator).
time configure_and_build build-tsan "viewer_tests parallel_tests emulator_tests" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DRADMESH_TSAN=ON -DRADMESH_BUILD_BENCHMARKS=OFF
run_tsan_tests() {
  echo "== build-tsan: threaded viewer tests, the thread pool"
  export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
  build-tsan/tests/viewer_tests --gtest_filter='SolverThread.*:Streaming.*'
  build-tsan/tests/parallel_tests
  build-tsan/tests/emulator_tests --gtest_filter='Determinism.*'
}
time run_tsan_tests
