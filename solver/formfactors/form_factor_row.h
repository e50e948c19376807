#pragma once
// A row of form factors: where one shooter's power goes. Every back end fills one the same way.
#include <cstddef>
#include <span>
#include <vector>

namespace radmesh {

// Where a shooter's power goes, as fractions of it.
struct FormFactorRow {
  int shooter = -1;
  std::vector<int> receivers;       // patches whose front the shooter sees, ascending
  std::vector<double> formFactors;  // F_ij for each receiver, > 0
  double backFaces = 0.0;           // reaches the unlit back of one-sided patches (absorbed there)
  double capturedFraction = 1.0;    // caught by the projection surface (the rest: not captured)
  bool reused = false;              // served from the form-factor cache, not computed
  // A directional shooter's row (FormFactorBackend::binDirections): the same directions again,
  // split by their bin (solver/formfactors/direction_bins.h). Empty for any other shooter.
  struct BinShare {
    int patch = 0;
    int bin = 0;
    double formFactor = 0.0;  // F_jb: of the bin's directions, those landing on the patch's front
  };
  std::vector<BinShare> binShares;   // by patch
  std::vector<double> binBackFaces;  // per bin: landing on backs
  std::vector<double> binTotals;     // per bin, F_b: all its directions the projection catches, hit or not

  double hitFraction() const;       // sum of formFactors, plus backFaces
  // Caught but hitting no patch: light leaving an open scene. Never negative.
  double escapedFraction() const;
  // Escaped plus backFaces: of a light's shot, what falls past the model or on its outside and never
  // enters it (Ledger::lightOutside).
  double outsideFraction() const;
  std::size_t bytes() const;        // memory the row holds
};

// The row from per-patch form factors of one shot: the patches seen from the front receive, what
// lands on backs is summed into backFaces, and zeros are dropped. The one assembly every back end uses.
FormFactorRow assembleRow(int shooter, double capturedFraction, std::span<const double> formFactors,
                          std::span<const char> seenFromFront);

}  // namespace radmesh
