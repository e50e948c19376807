#pragma once
// Running the solver in tests: form-factor rows from the native back end, and solves that check
// the invariants (finite, non-negative radiosity; a balanced ledger) at every iteration.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "solver/backends/native/native_backend.h"
#include "solver/radiosity/progressive_solver.h"
#include "tests/solver/patch_fixtures.h"

namespace radmesh::test {

inline SolveOptions optionsFor(Projection projection, int resolution = 64, int threads = 1) {
  SolveOptions o;
  o.projection = projection;
  o.resolution = resolution;
  o.threads = threads;
  return o;
}

inline double entry(const FormFactorRow& row, int receiver) {
  for (size_t k = 0; k < row.receivers.size(); ++k)
    if (row.receivers[k] == receiver) return row.formFactors[k];
  return 0.0;
}

// Rows of the given shooters.
inline std::vector<FormFactorRow> rowsOf(const TestScene& t, const SolveOptions& o, const std::vector<int>& shooters) {
  NativeBackend backend(t.scene, t.patches, o);
  std::vector<FormFactorRow> rows;
  backend.computeRows(shooters, rows);
  return rows;
}

// Area-weighted mean over the shooters of their form factors to the receivers: the
// area-to-area form factor, each shooter a quadrature point.
inline double areaFormFactor(const TestScene& t, const SolveOptions& o, const std::vector<int>& shooters,
                             const std::vector<int>& receivers) {
  double weighted = 0.0, area = 0.0;
  for (const FormFactorRow& row : rowsOf(t, o, shooters)) {
    double f = 0.0;
    for (int j : receivers) f += entry(row, j);
    weighted += f * t.patches[row.shooter].areaM2;
    area += t.patches[row.shooter].areaM2;
  }
  return weighted / area;
}

inline std::vector<int> range(int begin, int end) {
  std::vector<int> r(end - begin);
  std::iota(r.begin(), r.end(), begin);
  return r;
}

// Steps until done (or maxSteps), checking every iteration's invariants; true if it converged.
inline bool solveChecked(ProgressiveSolver& solver, int maxSteps = 1000000) {
  for (int step = 0; step < maxSteps && !solver.done(); ++step) {
    const IterationRecord& record = solver.step();
    const Ledger& l = record.ledger;
    if (!(l.imbalance() <= 1e-9) || l.absorbed < 0 || l.unshot < 0 || l.notCaptured < 0 || l.escaped < 0) {
      ADD_FAILURE() << "iteration " << record.iteration << ": ledger emitted " << l.emitted << " absorbed "
                    << l.absorbed << " unshot " << l.unshot << " not captured " << l.notCaptured
                    << " escaped " << l.escaped << " (imbalance " << l.imbalance() << ")";
      return false;
    }
  }
  for (size_t j = 0; j < solver.radiosity().size(); ++j)
    for (int c = 0; c < 3; ++c) {
      const double b = solver.radiosity()[j][c];
      if (!std::isfinite(b) || b < 0.0) {
        ADD_FAILURE() << "patch " << j << " has radiosity " << b;
        return false;
      }
    }
  return solver.done();
}

// Options for a fixed number of iterations: no stopping on convergence.
inline SolveOptions fixedIterations(SolveOptions o, int iterations) {
  o.until = 1.0;
  o.maxIterations = iterations;
  return o;
}

// Patches cut into elements (`how`: uniform or adaptive) no smaller than minElementM.
inline SolveOptions subdivided(SolveOptions o, Subdivide how, double minElementM) {
  o.subdivide = how;
  o.minElementM = minElementM;
  return o;
}

inline double areaMean(const std::vector<Patch>& patches, const std::vector<Rgb>& b, int channel = 0) {
  double weighted = 0.0, area = 0.0;
  for (size_t j = 0; j < patches.size(); ++j) {
    weighted += b[j][channel] * patches[j].areaM2;
    area += patches[j].areaM2;
  }
  return weighted / area;
}

}  // namespace radmesh::test
