#pragma once
// One solve on the solver thread (viewer/solver_thread.h): the solver, or the cells solver, and
// what the thread accumulates across its iterations. Private to solver_thread.cpp and solver_run.cpp.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/radiosity/cell_solver.h"
#include "viewer/solver_thread.h"

namespace radmesh {

struct SolverThread::Run {
  SolveSetup setup;
  std::uint64_t generation = 0;
  std::unique_ptr<ProgressiveSolver> solver;       // the whole scene at once, or
  std::unique_ptr<CellSolver> cells;               // cell by cell (setup.cells)
  std::shared_ptr<const CellPartition> partition;  // with cells
  int focus = -1;                                  // with cells: the cell solved first
  bool eyeInFocus = false;
  std::optional<Vec3> focusedEye;                  // the eye the focus was found for
  std::shared_ptr<const DisplayMesh> mesh;
  std::size_t meshedReceivers = 0;  // the receivers the mesh was built from
  std::shared_ptr<const std::vector<int>> cellOfReceiver;  // with cells: each of them, the cell it faces
  SceneSummary summary;
  bool sceneClosed = false;  // isClosed, once a start
  std::vector<ConvergencePoint> curve;
  std::shared_ptr<const ShotStats> lastShotStats;  // the last there was (cache hits have none)
  std::shared_ptr<const ItemBuffer> itemBuffer;
  int itemBufferShooter = -1;
  std::chrono::steady_clock::time_point itemBufferTime{};
  std::string checkpointMessage;  // the last save: where, or why not
  bool checkpointFailed = false;

  void add(const IterationRecord& record);
  bool done() const { return cells ? cells->done() : solver->done(); }
  bool exhausted() const { return cells ? cells->exhausted() : solver->exhausted(); }
  int lastShooter() const;  // cells: -1, no item buffer
  // What is drawn: the elements where patches are cut into them (a cells solve's, from its cells).
  std::size_t receiverCount() const;
  void buildMesh();

  // An iteration of the whole solve; a round of the cells solve, focused on the eye's cell first.
  void step(const std::optional<Vec3>& eye, int upAxis);
  void addRound(double seconds);  // a cells solve's point of the curve, where it stands now
  // The cell the eye stands in, else the cell nearest it; nothing before the eye is known. The
  // look-up passes over every patch: only when the eye has moved.
  void focusOn(const std::optional<Vec3>& eye, int upAxis);
  // With --subdivide adaptive, elements split as the light arrives: the display mesh is rebuilt
  // from them (before a publish, not every iteration: it passes over every element).
  void remeshIfSplit();
};

}  // namespace radmesh
