#include "viewer/solve_warnings.h"

#include <gtest/gtest.h>

#include <string>

#include "solver/io/scene_loader.h"
#include "tests/viewer/solver_thread_wait.h"

namespace radmesh {
namespace {

bool says(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// The panel warned only of light left unshot: light lost where no solve loses it (a lamp outside a
// closed room) was printed by `radmesh solve` alone.
TEST(SolveWarnings, ThePanelWarnsOfWhatSolvePrintsOnceStopped) {
  SolverSnapshot s;
  s.ledger.emitted = 100.0;
  s.ledger.escaped = 30.0;
  s.ledger.absorbed = 60.0;
  s.ledger.unshot = 10.0;
  s.sceneClosed = true;
  EXPECT_TRUE(solveWarnings(s).empty()) << "not stopped yet";
  s.done = true;
  const std::vector<std::string> closed = solveWarnings(s);
  EXPECT_TRUE(says(closed, "30.0% of the power left a closed scene or never entered it")) << closed.size();
  EXPECT_FALSE(says(closed, "far from converged"));  // 10 % unshot is not above the tenth
  s.sceneClosed = false;
  s.ledger.unshot = 40.0, s.ledger.absorbed = 30.0;
  const std::vector<std::string> open = solveWarnings(s);
  EXPECT_TRUE(says(open, "stopped with 40% of the power unshot"));
  EXPECT_FALSE(says(open, "left a closed scene"));
}

// The solver thread says whether its scene is closed, for those warnings.
TEST(SolveWarnings, TheSnapshotSaysWhetherTheSceneIsClosed) {
  for (const auto& [scene, closed] : {std::pair{"furnace", true}, std::pair{"cornell", false}}) {
    SolveSetup setup;
    setup.cellM = 0.25;
    setup.options.threads = 1;
    SolverThread thread(loadScene(scene), setup, /*playing=*/false);
    EXPECT_EQ(test::waitFor(thread, [](const SolverSnapshot& s) { return s.mesh != nullptr; })->sceneClosed, closed)
        << scene;
  }
}

}  // namespace
}  // namespace radmesh
