#include "solver/formfactors/form_factor_row.h"

namespace radmesh {

double FormFactorRow::hitFraction() const {
  double sum = backFaces;
  for (double f : formFactors) sum += f;
  return sum;
}

double FormFactorRow::outsideFraction() const { return escapedFraction() + backFaces; }

double FormFactorRow::escapedFraction() const {
  // Sums in another order differ in the last bits: a difference at rounding level is neither light
  // escaping a closed scene nor light created.
  const double escaped = capturedFraction - hitFraction();
  return escaped > 1e-12 * capturedFraction ? escaped : 0.0;
}

std::size_t FormFactorRow::bytes() const {
  return sizeof(FormFactorRow) + receivers.capacity() * sizeof(int) +
         formFactors.capacity() * sizeof(double) + binShares.capacity() * sizeof(BinShare) +
         (binBackFaces.capacity() + binTotals.capacity()) * sizeof(double);
}

FormFactorRow assembleRow(int shooter, double capturedFraction, std::span<const double> formFactors,
                          std::span<const char> seenFromFront) {
  FormFactorRow row;
  row.shooter = shooter;
  row.capturedFraction = capturedFraction;
  for (std::size_t j = 0; j < formFactors.size(); ++j) {
    const double f = formFactors[j];
    if (!(f > 0.0)) continue;
    if (seenFromFront[j]) {
      row.receivers.push_back(static_cast<int>(j));
      row.formFactors.push_back(f);
    } else {
      row.backFaces += f;
    }
  }
  return row;
}

}  // namespace radmesh
