#include "solver/radiosity/ledger.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "solver/scene/scene_error.h"

namespace radmesh {

double Ledger::input() const { return emitted + portalIn; }

double Ledger::imbalance() const {
  const double accounted = absorbed + unshot + notCaptured + escaped + portalOut;
  return input() > 0.0 ? std::abs(input() - accounted) / input() : std::abs(accounted);
}

double Ledger::unshotFraction() const {
  const double cameIn = input() - lightOutside;
  return cameIn > 0.0 ? unshot / cameIn : 0.0;
}

void checkLedger(const Ledger& l, int iteration) {
  if (l.imbalance() <= kLedgerTolerance) return;
  const std::string portals = l.portalIn > 0.0 || l.portalOut > 0.0
      ? fmt::format(" (a cell: portal in {:.17g} W, portal out {:.17g} W)", l.portalIn, l.portalOut) : "";
  throw SolveError(fmt::format(
      "iteration {}: the energy ledger does not balance: emitted {:.17g} W, absorbed {:.17g} W + unshot {:.17g} W "
      "+ not captured {:.17g} W + escaped {:.17g} W (absorbed by back faces {:.17g} W){}; imbalance {:.3g} of the "
      "emitted power, above {:.0e}. This is a fault in radmesh or its form-factor back end; the solve stops and "
      "nothing of it is written",
      iteration, l.emitted, l.absorbed, l.unshot, l.notCaptured, l.escaped, l.absorbedByBackFaces, portals,
      l.imbalance(), kLedgerTolerance));
}

}  // namespace radmesh
