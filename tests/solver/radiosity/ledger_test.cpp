#include "solver/radiosity/ledger.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace radmesh {
namespace {

// A balanced ledger of 100 W: `escaped` W left, `outside` W of a light never entered, `missed` W
// the single plane did not catch, the rest absorbed.
Ledger ledgerOf(double escaped, double outside, double missed) {
  Ledger l;
  l.emitted = 100.0;
  l.escaped = escaped;
  l.lightOutside = outside;
  l.notCaptured = missed;
  l.absorbed = 100.0 - escaped - missed;
  return l;
}

bool says(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// A closed scene loses nothing but seams' rounding: 2 % gone (an emitter on a wall, a light outside
// the model) is named. An open scene loses what its openings let out, and even 80 % of it is no
// fault; all of it is (an emitter a nanometre from a wall sent everything past it). The sun on a
// building's outside never entered, and is no loss in an open scene.
TEST(Ledger, LightLostWhereNoSolveLosesItIsNamed) {
  EXPECT_TRUE(lostLightWarnings(ledgerOf(0.5, 0.0, 0.0), true).empty());
  EXPECT_TRUE(says(lostLightWarnings(ledgerOf(2.0, 0.0, 0.0), true), "2.0% of the power left a closed scene"));
  EXPECT_TRUE(says(lostLightWarnings(ledgerOf(60.0, 60.0, 0.0), true), "60.0% of the power left a closed scene or never entered"));
  EXPECT_TRUE(lostLightWarnings(ledgerOf(80.0, 0.0, 0.0), false).empty());
  EXPECT_TRUE(lostLightWarnings(ledgerOf(95.0, 90.0, 0.0), false).empty());  // 5 of the 10 W that entered
  EXPECT_TRUE(says(lostLightWarnings(ledgerOf(100.0, 0.0, 0.0), false), "100.0% of the power that entered the scene left"));
  EXPECT_TRUE(lostLightWarnings(ledgerOf(0.0, 0.0, 9.0), true).empty());  // a shot's 8.3 %
  EXPECT_TRUE(says(lostLightWarnings(ledgerOf(0.0, 0.0, 80.0), false), "the single plane missed 80.0% of the power"));
  EXPECT_TRUE(lostLightWarnings(Ledger{}, true).empty());  // nothing emitted: nothing lost
  // An open scene that none of the light entered (a sun along a flat model) is all dark, "100 %" converged.
  EXPECT_TRUE(says(lostLightWarnings(ledgerOf(100.0, 100.0, 0.0), false), "none of the lights' power entered the model"));
}

// More than 5 % of what came in absorbed on the backs of one-sided surfaces is named, with the fix;
// the sun on a building's outside (walls facing in) is booked there too, but never came in.
TEST(Ledger, LightOnBackFacesIsNamedAboveATwentiethOfTheLight) {
  Ledger l = ledgerOf(0.0, 0.0, 0.0);
  l.absorbedByBackFaces = 4.0;
  EXPECT_TRUE(lostLightWarnings(l, true).empty());
  l.absorbedByBackFaces = 6.0;
  EXPECT_TRUE(says(lostLightWarnings(l, true), "6.0% of the emitted power was absorbed on the backs of one-sided surfaces"));
  EXPECT_TRUE(says(lostLightWarnings(l, true), "as two faces back to back or give it thickness, or in glTF make its material doubleSided"));
  l.lightOutside = l.lightOnBackFaces = l.absorbedByBackFaces = 90.0;  // the sun on the outside: no loss
  EXPECT_TRUE(lostLightWarnings(l, false).empty());
  l.absorbedByBackFaces = 91.0;  // and 1 W of the 10 that came in
  EXPECT_TRUE(says(lostLightWarnings(l, false), "10.0% of the power that came in was absorbed on the backs"));
}

// The sun's power that never came in is partly past the model (escaped) and partly on its outside
// (back faces): each is weighed against its own kind of loss, not against the whole. Weighing all of
// it against the backs hid 6 of the 10 W that came in falling on backs indoors; against escape, all
// of the 10 W leaving again.
TEST(Ledger, TheSunPastTheModelHidesNoLossInsideIt) {
  Ledger l;
  l.emitted = 100.0;
  l.lightOutside = 90.0;  // 60 W past the building, 30 W on its outside walls
  l.lightOnBackFaces = 30.0;
  l.escaped = 60.0;
  l.absorbedByBackFaces = 36.0;
  l.absorbed = 40.0;
  EXPECT_TRUE(says(lostLightWarnings(l, false), "60.0% of the power that came in was absorbed on the backs"));
  l.escaped = 70.0;  // and the 10 W that came in all left again
  l.absorbedByBackFaces = 30.0;
  l.absorbed = 30.0;
  EXPECT_TRUE(says(lostLightWarnings(l, false), "100.0% of the power that entered the scene left"));
}

}  // namespace
}  // namespace radmesh
