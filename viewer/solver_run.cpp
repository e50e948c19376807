// One solve on the solver thread: how it starts (meshing, a checkpoint to resume), steps, saves,
// and the snapshots the UI gets of it.
#include "viewer/solver_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "parallel/thread_pool.h"
#include "solver/cells/cell_at.h"
#include "solver/cells/find_cells.h"
#include "solver/io/atomic_file.h"
#include "solver/io/builtin_scenes.h"
#include "solver/io/output_path.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/checkpoint.h"
#include "solver/radiosity/effects_plan.h"
#include "solver/scene/scene_error.h"
#include "viewer/exposure.h"

namespace radmesh {

namespace {

using Clock = std::chrono::steady_clock;

int lastShooter(const ProgressiveSolver& solver) {
  const auto& history = solver.history();
  return history.empty() || history.back().shooters.empty() ? -1 : history.back().shooters.front();
}

// The curve's next point: this iteration's figures, the running sums carried on.
ConvergencePoint nextPoint(const std::vector<ConvergencePoint>& curve, const IterationRecord& record) {
  ConvergencePoint point = curve.empty() ? ConvergencePoint{} : curve.back();
  point.iteration = record.iteration;
  point.convergence = record.convergence;
  point.unshotFraction = record.ledger.unshotFraction();
  point.hostSeconds += record.seconds;
  point.shot = record.shotStats;
  if (record.shotStats) point.machineSeconds += record.shotStats->machineSeconds;
  return point;
}

}  // namespace

void SolverThread::Run::add(const IterationRecord& record) {
  curve.push_back(nextPoint(curve, record));
  if (record.shotStats) lastShotStats = record.shotStats;
}

int SolverThread::Run::lastShooter() const { return cells ? -1 : radmesh::lastShooter(*solver); }

void SolverThread::Run::step(const std::optional<Vec3>& eye, int upAxis) {
  if (!cells) return add(solver->step());
  focusOn(eye, upAxis);
  const auto start = Clock::now();
  cells->round();
  addRound(std::chrono::duration<double>(Clock::now() - start).count());
}

void SolverThread::Run::addRound(double seconds) {
  IterationRecord record;  // the building's, over the round: C has no meaning across cells
  record.iteration = cells->iterations();
  record.ledger = cells->ledger();
  record.seconds = seconds;
  add(record);
}

std::size_t SolverThread::Run::receiverCount() const {
  if (!cells) return solver->elements().size();
  std::size_t count = 0;
  for (const CellFigures& cell : cells->cellFigures()) count += static_cast<std::size_t>(cell.elements);
  return count;
}

void SolverThread::Run::buildMesh() {
  if (!cells) {
    mesh = std::make_shared<const DisplayMesh>(buildDisplayMesh(solver->elements()));
  } else {
    const Elements elements = cells->elements();
    mesh = std::make_shared<const DisplayMesh>(buildDisplayMesh(elements.elements));
    auto cellOf = std::make_shared<std::vector<int>>();
    for (int p : elements.patchOf) cellOf->push_back(partition->cellOfPatch[p]);
    cellOfReceiver = std::move(cellOf);
  }
  meshedReceivers = receiverCount();
}

void SolverThread::Run::remeshIfSplit() {
  if (receiverCount() != meshedReceivers) buildMesh();
}

void SolverThread::Run::focusOn(const std::optional<Vec3>& eye, int upAxis) {
  if (!eye || eye == focusedEye) return;
  focusedEye = eye;
  Vec3 up(0.0);
  up[upAxis] = 1.0;
  int cell = cellBelow(cells->patches(), *partition, *eye, up);
  eyeInFocus = cell != kOutsideCell;
  if (!eyeInFocus) cell = nearestCell(*partition, *eye);
  if (cell != focus) cells->focus(cell);
  focus = cell;
}

std::unique_ptr<SolverThread::Run> SolverThread::makeRun(const SolveSetup& setup, std::uint64_t generation,
                                                        const std::string& resumePath,
                                                        const std::optional<Vec3>& eye) {
  auto run = std::make_unique<Run>();
  run->setup = setup;
  run->setup.options.formFactorCacheBytes = formFactorCacheBytes(setup.options.backend, setup.cacheMb);
  // --threads 0, or the panel's: every hardware thread but one (at least one), left to the window's
  // drawing, which llvmpipe does on the CPU too.
  if (setup.options.threads == 0) run->setup.options.threads = std::max(1, ThreadPool::sizeFor(0) - 1);
  defaultMinElement(run->setup.options, setup.cellM);
  run->generation = generation;
  std::vector<Patch> patches = meshScene(scene_, setup.cellM);
  run->summary = summarizeScene(scene_, patches, setup.cellM);
  if (setup.cells) {
    requireCellsOptions(setup.options);
    run->sceneClosed = isClosed(scene_);  // the cells' plans are each cell's
    run->partition = std::make_shared<const CellPartition>(findCells(scene_, patches));
    run->cells = std::make_unique<CellSolver>(scene_, std::move(patches), *run->partition, run->setup.options,
                                              CellSolveSettings{setup.cellM, setup.exchangeShots, setup.portalBins});
    run->focusOn(eye, scene_.upAxis);
  } else {
    run->solver = std::make_unique<ProgressiveSolver>(scene_, std::move(patches), run->setup.options);
    run->sceneClosed = run->solver->effectsPlan().closed;
  }
  if (!resumePath.empty() && run->solver) {
    resumeFromCheckpoint(resumePath, *run->solver);
    for (const IterationRecord& record : run->solver->history()) run->add(record);
    run->checkpointMessage = "resumed from " + resumePath;
  } else if (!resumePath.empty()) {
    resumeCellsFromCheckpoint(resumePath, scene_, *run->cells);
    // Where it stands, from the start: the panel said 0 iterations until the next round. (The
    // rounds before are not saved: the curve starts here.)
    run->addRound(0.0);
    run->checkpointMessage = "resumed from " + resumePath + " after round " + std::to_string(run->cells->rounds());
  }
  run->buildMesh();
  return run;
}

std::unique_ptr<SolverThread::Run> SolverThread::startRun(const SolveSetup& setup, std::uint64_t generation,
                                                         const std::optional<Vec3>& eye) {
  try {
    return makeRun(setup, generation, "", eye);
  } catch (const std::exception& e) {
    publishFailure(setup, e);
    return nullptr;
  }
}

void SolverThread::save(Run& run, const std::string& path) {
  // Said in the panel, where the path is typed: its fixes name the box, not --checkpoint.
  constexpr const char* kBox = "in the box beside Save checkpoint";
  run.checkpointFailed = true;
  if (path.empty()) {  // an empty box in the panel: said, not ignored
    run.checkpointMessage = fmt::format("no checkpoint saved: type a path {}", kBox);
    return;
  }
  if (namesOnlyAnExtension(path)) {
    run.checkpointMessage =
        fmt::format("not saved: {} is an extension alone, which would write a hidden file: type a name before it {}",
                    path, kBox);
    return;
  }
  if (!scene_.file.empty() && sameFile(path, scene_.file)) {
    run.checkpointMessage = fmt::format("not saved: {} is the scene itself: type another path {}", path, kBox);
    return;
  }
  if (holdsSomethingElse(path)) {
    run.checkpointMessage =
        fmt::format("not saved: {} is a file that is not a radmesh checkpoint: type another path {}", path, kBox);
    return;
  }
  try {
    if (run.cells) {
      writeCellsCheckpoint(path, scene_, *run.cells);
      run.checkpointMessage = "saved " + path + " after round " + std::to_string(run.cells->rounds());
    } else {
      writeCheckpoint(path, *run.solver);
      run.checkpointMessage = "saved " + path + " after iteration " + std::to_string(run.solver->history().size());
    }
    run.checkpointFailed = false;
  } catch (const CheckpointWriteError& e) {
    run.checkpointMessage = fmt::format("not saved: {}: type a path in a writable folder with room {}", e.reason(), kBox);
  }
}

std::shared_ptr<const CellsProgress> SolverThread::cellsProgress(const Run& run) {
  auto progress = std::make_shared<CellsProgress>();
  const std::vector<CellFigures> figures = run.cells->cellFigures();
  for (size_t c = 0; c < figures.size(); ++c)
    progress->cells.push_back({figures[c].name, figures[c].iterations, figures[c].ledger.unshotFraction(),
                               run.cells->portalDistance(static_cast<int>(c))});
  progress->rounds = run.cells->rounds();
  progress->focus = run.focus;
  progress->eyeInFocus = run.eyeInFocus;
  progress->partition = run.partition;
  progress->cellOfReceiver = run.cellOfReceiver;
  return progress;
}

void SolverThread::publish(const Run& run) {
  auto snapshot = std::make_shared<SolverSnapshot>();
  snapshot->generation = run.generation;
  snapshot->setup = run.setup;
  snapshot->mesh = run.mesh;
  snapshot->summary = run.summary;
  snapshot->sceneClosed = run.sceneClosed;
  snapshot->receivers = run.receiverCount();
  if (run.cells) {
    snapshot->vertexB = vertexRadiosity(*run.mesh, run.cells->displayElementRadiosity());
    snapshot->cells = cellsProgress(run);
  } else {
    snapshot->effects = run.solver->effectsPlan().effects;
    snapshot->vertexB = vertexRadiosity(*run.mesh, run.solver->displayElementRadiosity());
    const auto& history = run.solver->history();
    if (!history.empty()) {
      snapshot->lastShooters = history.back().shooters;
      snapshot->lastShooterElements = run.solver->elementsOf(snapshot->lastShooters);
      snapshot->lastCapturedFraction = history.back().capturedFraction;
    }
  }
  // Here rather than on the UI's thread: it sorts every triangle.
  snapshot->exposure = autoExposure(*run.mesh, snapshot->vertexB);
  snapshot->lastShotStats = run.lastShotStats;
  snapshot->itemBuffer = run.itemBuffer;
  snapshot->itemBufferShooter = run.itemBufferShooter;
  snapshot->curve = run.curve;
  snapshot->ledger = run.cells ? run.cells->ledger() : run.solver->ledger();
  snapshot->done = run.done();
  snapshot->checkpointMessage = run.checkpointMessage;
  snapshot->checkpointFailed = run.checkpointFailed;
  snapshot->exhausted = run.exhausted();
  std::lock_guard lock(mutex_);
  snapshot->playing = playing_;
  snapshot->stepsLeft = pendingSteps_;
  latest_ = std::move(snapshot);
}

void SolverThread::publishFailure(const SolveSetup& setup, const std::exception& error) {
  auto snapshot = std::make_shared<SolverSnapshot>();
  snapshot->setup = setup;
  snapshot->error = error.what();
  snapshot->errorIsInput = dynamic_cast<const SceneError*>(&error) || dynamic_cast<const OptionError*>(&error);
  std::lock_guard lock(mutex_);
  snapshot->generation = generation_;
  snapshot->playing = playing_;
  latest_ = std::move(snapshot);
}

}  // namespace radmesh
