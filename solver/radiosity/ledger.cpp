#include "solver/radiosity/ledger.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "solver/formfactors/form_factor_row.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

double Ledger::input() const { return emitted + portalIn; }

double Ledger::imbalance() const {
  const double accounted = absorbed + unshot + notCaptured + escaped + portalOut;
  return input() > 0.0 ? std::abs(input() - accounted) / input() : std::abs(accounted);
}

void bookShotLosses(Ledger& l, const FormFactorRow& row, double powerW, bool fromLight) {
  l.notCaptured += powerW * (1.0 - row.capturedFraction);
  l.escaped += powerW * row.escapedFraction();
  l.absorbed += powerW * row.backFaces;
  l.absorbedByBackFaces += powerW * row.backFaces;
  if (!fromLight) return;
  l.lightOutside += powerW * row.outsideFraction();
  l.lightOnBackFaces += powerW * row.backFaces;
}

std::vector<std::string> lostLightWarnings(const Ledger& l, bool sceneClosed) {
  std::vector<std::string> warnings;
  if (!(l.input() > 0.0)) return warnings;
  // The lights' power that fell outside the model (the sun on a building's outside) is no loss in
  // an open scene: only what entered is weighed there.
  const double neverEntered = l.lightOutside / l.input();
  const double entered = l.cameIn();
  const double lightPast = l.lightOutside - l.lightOnBackFaces;  // the lights' part of escaped
  const double leftAfterEntering = entered > 0.0 ? std::max(0.0, l.escaped - lightPast) / entered : 0.0;
  // Nothing at all came in: every radiosity is zero, whatever the scene.
  if (!sceneClosed && neverEntered > 1.0 - 1e-9) {
    warnings.push_back("none of the lights' power entered the model, so every radiosity is zero: is the sun along a "
                       "flat model, or a light outside it facing away?");
    return warnings;
  }
  const double lost = sceneClosed ? std::max(neverEntered, leftAfterEntering) : leftAfterEntering;
  if (lost > (sceneClosed ? kLostInClosedScene : kLostInOpenScene))
    warnings.push_back(fmt::format(
        "{:.1f}% of the power {}: is a light outside the model or facing away from it, or an emitter nearer a surface "
        "than the projection resolves (move it off by a millimetre)?",
        100.0 * lost, sceneClosed ? "left a closed scene or never entered it" : "that entered the scene left it"));
  if (l.notCaptured / l.input() > kPlaneMissed)
    warnings.push_back(fmt::format(
        "the single plane missed {:.1f}% of the power (each shot's grazing light, compounded by interreflection), so "
        "the scene is darker than it should be: --projection hemicube catches all of it",
        100.0 * l.notCaptured / l.input()));
  // The lights' power on the model's outside (the sun on walls facing in) is booked there too, and
  // is no loss: only the rest is weighed.
  const double onBacks = entered > 0.0 ? std::max(0.0, l.absorbedByBackFaces - l.lightOnBackFaces) / entered : 0.0;
  if (onBacks > kBackFacesAbsorbed)
    warnings.push_back(fmt::format(
        "{:.1f}% of {} was absorbed on the backs of one-sided surfaces (radmesh reads every surface one-sided, as "
        "RenderPark does by default: its back is black), so the scene is darker than it should be: model a surface "
        "lit from both sides (a partition, a table top) as two faces back to back or give it thickness, or in glTF "
        "make its material doubleSided",
        100.0 * onBacks, l.unshotBasis()));
  return warnings;
}

std::string lightOutsideSentence(const Ledger& l) {
  if (!(l.lightOutside > 0.0 && l.input() > 0.0)) return "";
  return fmt::format("of it, {:.6g} W ({:.1f}%) is the lights' that fell on the model's outside or past it and never "
                     "came in; the unshot fraction is of the {:.6g} W that did",
                     l.lightOutside, 100.0 * l.lightOutside / l.input(), l.cameIn());
}

std::string absorbedTerm(const Ledger& l) {
  return fmt::format("absorbed {:.6g} ({:.6g} on back faces)", l.absorbed, l.absorbedByBackFaces);
}

const char* Ledger::unshotBasis() const {
  return lightOutside > 0.0 ? "the power that came in" : "the emitted power";
}

double Ledger::cameIn() const { return input() - lightOutside; }

double Ledger::unshotFraction() const {
  const double in = cameIn();
  return in > 0.0 ? unshot / in : 0.0;
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
