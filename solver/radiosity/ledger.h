#pragma once
// The energy ledger: where every watt a solve was given went, checked after every iteration.
#include <array>
#include <string>
#include <vector>

namespace radmesh {

struct FormFactorRow;

// Where the emitted power went, in watts summed over RGB. Balances:
// emitted + portalIn = absorbed + unshot + notCaptured + escaped + portalOut
// (the portal terms are those of one cell of a cells solve, solver/radiosity/cell_solver.h; zero
// otherwise).
struct Ledger {
  double emitted = 0.0;
  double absorbed = 0.0;     // absorbed by patches: (1 - rho) of what reached them
  double unshot = 0.0;       // reflected but not yet shot on: sum of dB_j * A_j
  double notCaptured = 0.0;  // left the shooter outside the projection surface (the plane's miss)
  double escaped = 0.0;      // captured but hit no patch: light leaving an open scene
  double absorbedByBackFaces = 0.0;  // part of absorbed: reached the unlit back of a one-sided patch
  double portalOut = 0.0;    // reached the cell's portal patches: leaves for the neighbour cells
  double portalIn = 0.0;     // arrived from the neighbour cells, to be shot from the portal patches
  // Part of escaped and absorbedByBackFaces: what a light's shot sent past the model or onto its
  // outside (most of the sun on a building), which never entered it.
  double lightOutside = 0.0;
  double lightOnBackFaces = 0.0;  // part of lightOutside: the lights' on the backs of one-sided patches
  // Every term, for what handles them all alike (sums, checks, checkpoints, messages between ranks).
  static constexpr std::array kTerms{&Ledger::emitted,     &Ledger::absorbed,         &Ledger::unshot,
                                     &Ledger::notCaptured, &Ledger::escaped,          &Ledger::absorbedByBackFaces,
                                     &Ledger::portalOut,   &Ledger::portalIn,         &Ledger::lightOutside,
                                     &Ledger::lightOnBackFaces};
  double input() const;      // emitted + portalIn: all the power the solve has had to distribute
  double imbalance() const;  // |input - (absorbed + unshot + notCaptured + escaped + portalOut)| / input
  // unshot / (input - lightOutside): what is left to distribute of what came in (0 if nothing did).
  // Not of input: the sun on a building's outside would make 1 % of it more than all its rooms' light.
  double unshotFraction() const;
  // input - lightOutside: the power that came into the model, of which unshotFraction is a share.
  double cameIn() const;
  // What unshotFraction is a fraction of, in words: "the emitted power", or "the power that came in"
  // when lights sent some onto the model's outside.
  const char* unshotBasis() const;
};

// Books where a shot of powerW along `row` went other than onto its receivers' fronts: not captured,
// escaped, or absorbed on the backs of one-sided patches. A light's shot (`fromLight`) books its
// escape and backs as lightOutside too: that light never came into the model.
void bookShotLosses(Ledger& ledger, const FormFactorRow& row, double powerW, bool fromLight);

// Throws SolveError when the ledger does not balance to kLedgerTolerance of its input, naming
// `iteration` and every term. Every iteration, in every build: numbers that do not balance are never
// shown or written.
void checkLedger(const Ledger& ledger, int iteration);
// What the ledger vouches for, as a fraction of the emitted power: rounding over millions of
// updates stays far below; checkLedger refuses an imbalance above it.
inline constexpr double kLedgerTolerance = 1e-9;

// Light a balanced ledger lost where a solve should not lose it, each a sentence for a warning:
// more than kLostInClosedScene of the power left a closed scene or never entered it (a light outside
// the model), more than kLostInOpenScene of what entered an open one left it (an emitter nearer a
// surface than the projection resolves sends all its light past it), the single plane missed
// more than kPlaneMissed of it (its 8.3 % a shot, compounded by interreflection), or more than
// kBackFacesAbsorbed of what came in fell on the unlit backs of one-sided surfaces (a partition
// modelled as one face, lit from both sides). Empty: none.
std::vector<std::string> lostLightWarnings(const Ledger& ledger, bool sceneClosed);
// The sentence a solve prints under its ledger when lights sent power onto the model's outside or
// past it (the sun on a roof): that power is in `emitted` but never came in, and the unshot fraction
// is of the rest. Empty when none did.
std::string lightOutsideSentence(const Ledger& ledger);
// The ledger line's absorbed term with its part on back faces: "absorbed 265.822 (29.4 on back faces)".
std::string absorbedTerm(const Ledger& ledger);
inline constexpr double kLostInClosedScene = 0.01;
inline constexpr double kLostInOpenScene = 0.9;
inline constexpr double kPlaneMissed = 0.10;
inline constexpr double kBackFacesAbsorbed = 0.05;

}  // namespace radmesh
