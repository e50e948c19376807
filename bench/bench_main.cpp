// The main of every benchmark program: Google Benchmark's, except that an exception (a scene that
// does not load, a SolveError when the energy ledger stops balancing) is printed and exits
// non-zero instead of aborting, and the run that threw reports no figure.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  try {
    benchmark::RunSpecifiedBenchmarks();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  benchmark::Shutdown();
  return 0;
}
