#include "viewer/solver_thread.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <optional>
#include <sys/resource.h>
#include <unistd.h>
#include <utility>

#include "solver/cells/cell_at.h"
#include "solver/cells/find_cells.h"
#include "solver/radiosity/cell_solver.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/checkpoint.h"
#include "solver/scene/scene_error.h"
#include "viewer/exposure.h"

namespace radmesh {

namespace {

using Clock = std::chrono::steady_clock;

// Publishing costs a pass over every vertex; while playing, the UI needs no more than this.
constexpr auto kPublishInterval = std::chrono::milliseconds(40);
// The solver thread's nice value, above the drawing thread's 0 (Linux's nice is per thread).
constexpr int kSolverNice = 10;
// An item buffer costs a projection of every patch: while playing, one now and then is enough.
constexpr auto kItemBufferInterval = std::chrono::milliseconds(500);

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
  SceneSummary summary;
  std::vector<ConvergencePoint> curve;
  std::shared_ptr<const ShotStats> lastShotStats;  // the last there was (cache hits have none)
  std::shared_ptr<const ItemBuffer> itemBuffer;
  int itemBufferShooter = -1;
  Clock::time_point itemBufferTime{};
  std::string checkpointMessage;  // the last save: where, or why not

  void add(const IterationRecord& record) {
    curve.push_back(nextPoint(curve, record));
    if (record.shotStats) lastShotStats = record.shotStats;
  }
  bool done() const { return cells ? cells->done() : solver->done(); }
  bool exhausted() const { return cells ? cells->exhausted() : solver->exhausted(); }
  int lastShooter() const { return cells ? -1 : radmesh::lastShooter(*solver); }  // cells: no item buffer
  // What is drawn: the elements where patches are cut into them.
  const std::vector<Patch>& receivers() const { return cells ? cells->patches() : solver->elements(); }

  // An iteration of the whole solve; a round of the cells solve, focused on the eye's cell first.
  void step(const std::optional<Vec3>& eye, int upAxis) {
    if (!cells) return add(solver->step());
    focusOn(eye, upAxis);
    const auto start = Clock::now();
    cells->round();
    IterationRecord record;  // the building's, over the round: C has no meaning across cells
    record.iteration = cells->iterations();
    record.ledger = cells->ledger();
    record.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    add(record);
  }

  // The cell the eye stands in, else the cell nearest it; nothing before the eye is known. The
  // look-up passes over every patch: only when the eye has moved.
  void focusOn(const std::optional<Vec3>& eye, int upAxis) {
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
};

SolverThread::SolverThread(Scene scene, const SolveSetup& setup, bool playing, std::string resumePath)
    : scene_(std::move(scene)), playing_(playing), pendingSetup_(setup), pendingResume_(std::move(resumePath)) {
  auto first = std::make_shared<SolverSnapshot>();
  first->setup = setup;
  first->playing = playing;
  latest_ = std::move(first);
  thread_ = std::thread(&SolverThread::loop, this);
}

SolverThread::~SolverThread() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void SolverThread::play() {
  {
    std::lock_guard lock(mutex_);
    playing_ = true;
  }
  wake_.notify_all();
}

void SolverThread::pause() {
  std::lock_guard lock(mutex_);
  playing_ = false;
  pendingSteps_ = 0;
}

void SolverThread::step(int iterations) {
  {
    std::lock_guard lock(mutex_);
    playing_ = false;
    pendingSteps_ += std::max(0, iterations);
  }
  wake_.notify_all();
}

void SolverThread::restart(const SolveSetup& setup) {
  {
    std::lock_guard lock(mutex_);
    pendingSetup_ = setup;
    restartPending_ = true;
  }
  wake_.notify_all();
}

void SolverThread::saveCheckpoint(const std::string& path) {
  {
    std::lock_guard lock(mutex_);
    pendingCheckpoint_ = path;
  }
  wake_.notify_all();
}

void SolverThread::setStoppingRule(double until, double untilUnshot) {
  {
    std::lock_guard lock(mutex_);
    SolveOptions checked = pendingSetup_.options;
    checked.until = until;
    checked.untilUnshot = untilUnshot;
    validateOptions(checked);
    if (pendingSetup_.cells && until < 1.0)
      throw OptionError("a cells solve stops on the unshot power of the whole building alone: leave C at 1");
    pendingSetup_.options = checked;
    stoppingRulePending_ = true;
  }
  wake_.notify_all();
}

void SolverThread::setEye(const Vec3& eye) {
  std::lock_guard lock(mutex_);
  eye_ = eye;
}

void SolverThread::setItemBufferWanted(bool wanted) {
  {
    std::lock_guard lock(mutex_);
    itemBufferWanted_ = wanted;
  }
  wake_.notify_all();
}

std::shared_ptr<const SolverSnapshot> SolverThread::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

void SolverThread::loop() {
  // Drawing comes first: on a machine with fewer free cores than threads, the window keeps its
  // frame rate and the solve (with the pool threads it starts, which inherit this) takes the rest.
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kSolverNice);
  std::unique_ptr<Run> run;
  Clock::time_point lastPublish{};
  for (;;) {
    enum class Work { Restart, StoppingRule, Checkpoint, Step, ItemBuffer } work = Work::Step;
    SolveSetup setup;
    std::string resumePath, checkpointPath;
    std::uint64_t generation = 0;
    std::optional<Vec3> eye;
    {
      std::unique_lock lock(mutex_);
      // Paused, the thread still wakes to show the item buffer of the last shot once it is asked for.
      auto itemBufferMissing = [&] {
        return run && itemBufferWanted_ && run->lastShooter() != run->itemBufferShooter;
      };
      // Playing stops at the stopping rule; a step asked for goes past it, until nothing is left.
      auto canStep = [&] {
        return run && ((playing_ && !run->done()) || (pendingSteps_ > 0 && !run->exhausted()));
      };
      wake_.wait(lock, [&] {
        return stop_ || restartPending_ || (run && stoppingRulePending_) || (run && !pendingCheckpoint_.empty()) ||
               canStep() || itemBufferMissing();
      });
      if (stop_) return;
      eye = eye_;
      if (restartPending_) {
        work = Work::Restart;
        restartPending_ = false;
        stoppingRulePending_ = false;  // the new setup carries it
        setup = pendingSetup_;
        resumePath = std::exchange(pendingResume_, {});
        generation = ++generation_;
      } else if (stoppingRulePending_) {
        work = Work::StoppingRule;
        stoppingRulePending_ = false;
        setup = pendingSetup_;
      } else if (run && !pendingCheckpoint_.empty()) {
        work = Work::Checkpoint;
        checkpointPath = std::exchange(pendingCheckpoint_, {});
      } else if (canStep()) {
        if (pendingSteps_ > 0) --pendingSteps_;
      } else {
        work = Work::ItemBuffer;
      }
    }

    if (work == Work::Restart) {
      run = startRun(setup, generation, resumePath, eye);
      if (run) publish(*run);
      lastPublish = Clock::now();
      continue;
    }
    if (work == Work::Checkpoint) {
      save(*run, checkpointPath);
      publish(*run);
      continue;
    }
    if (work == Work::StoppingRule) {
      run->setup.options.until = setup.options.until;
      run->setup.options.untilUnshot = setup.options.untilUnshot;
      // Validated by the caller.
      if (run->cells)
        run->cells->setUntilUnshot(setup.options.untilUnshot);
      else
        run->solver->setStoppingRule(setup.options.until, setup.options.untilUnshot);
      publish(*run);
      continue;
    }
    if (work == Work::ItemBuffer) {
      refreshItemBuffer(*run, true);
      publish(*run);
      continue;
    }
    try {
      run->step(eye, scene_.upAxis);
    } catch (const std::exception& e) {
      publishFailure(run->setup, e.what());
      run.reset();
      continue;
    }
    bool moreToDo = false;
    {
      std::lock_guard lock(mutex_);
      moreToDo = ((playing_ && !run->done()) || pendingSteps_ > 0) && !restartPending_;
    }
    // While iterating, publish at the UI's pace; the last iteration before a pause always.
    const bool finished = !moreToDo || run->exhausted();
    if (finished || Clock::now() - lastPublish >= kPublishInterval) {
      refreshItemBuffer(*run, finished);
      publish(*run);
      lastPublish = Clock::now();
    }
  }
}

std::unique_ptr<SolverThread::Run> SolverThread::startRun(const SolveSetup& setup, std::uint64_t generation,
                                                         const std::string& resumePath,
                                                         const std::optional<Vec3>& eye) {
  try {
    auto run = std::make_unique<Run>();
    run->setup = setup;
    run->generation = generation;
    std::vector<Patch> patches = meshScene(scene_, setup.cellM);
    run->summary = summarizeScene(scene_, patches, setup.cellM);
    if (setup.cells) {
      if (setup.options.backend != Backend::Native)
        throw OptionError("--cells auto runs on the native back end: give --backend native, or --cells off");
      run->partition = std::make_shared<const CellPartition>(findCells(scene_, patches));
      run->cells = std::make_unique<CellSolver>(scene_, std::move(patches), *run->partition, setup.options,
                                                CellSolveSettings{setup.cellM, setup.exchangeShots, setup.portalBins});
      run->focusOn(eye, scene_.upAxis);
    } else {
      run->solver = std::make_unique<ProgressiveSolver>(scene_, std::move(patches), setup.options);
    }
    if (!resumePath.empty() && run->solver) {
      resumeFromCheckpoint(resumePath, *run->solver);
      for (const IterationRecord& record : run->solver->history()) run->add(record);
      run->checkpointMessage = "resumed from " + resumePath;
    }
    run->mesh = std::make_shared<const DisplayMesh>(buildDisplayMesh(run->receivers()));
    return run;
  } catch (const std::exception& e) {
    publishFailure(setup, e.what());
    return nullptr;
  }
}

void SolverThread::save(Run& run, const std::string& path) {
  if (run.cells) {
    run.checkpointMessage = "a cells solve keeps no checkpoint (it is one solve per cell): restart with --cells off";
    return;
  }
  try {
    writeCheckpoint(path, *run.solver);
    run.checkpointMessage = "saved " + path + " after iteration " + std::to_string(run.solver->history().size());
  } catch (const std::exception& e) {
    run.checkpointMessage = e.what();
  }
}

void SolverThread::refreshItemBuffer(Run& run, bool finished) {
  const int shooter = run.lastShooter();
  {
    std::lock_guard lock(mutex_);
    if (!itemBufferWanted_) return;
  }
  const auto now = Clock::now();
  if (shooter < 0 || shooter == run.itemBufferShooter || (!finished && now - run.itemBufferTime < kItemBufferInterval))
    return;
  run.itemBufferShooter = shooter;  // also after a failure: never retried in a loop
  try {
    run.itemBuffer = std::make_shared<const ItemBuffer>(run.solver->backend().singlePlaneItemBuffer(shooter));
  } catch (const std::exception&) {
    run.itemBuffer.reset();  // the panel says it is unavailable; the solve goes on
  }
  run.itemBufferTime = now;
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
  return progress;
}

void SolverThread::publish(const Run& run) {
  auto snapshot = std::make_shared<SolverSnapshot>();
  snapshot->generation = run.generation;
  snapshot->setup = run.setup;
  snapshot->mesh = run.mesh;
  snapshot->summary = run.summary;
  if (run.cells) {
    snapshot->vertexB = vertexRadiosity(*run.mesh, run.cells->displayRadiosity());
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
  snapshot->exhausted = run.exhausted();
  std::lock_guard lock(mutex_);
  snapshot->playing = playing_;
  latest_ = std::move(snapshot);
}

void SolverThread::publishFailure(const SolveSetup& setup, const std::string& error) {
  auto snapshot = std::make_shared<SolverSnapshot>();
  snapshot->setup = setup;
  snapshot->error = error;
  std::lock_guard lock(mutex_);
  snapshot->generation = generation_;
  snapshot->playing = playing_;
  latest_ = std::move(snapshot);
}

}  // namespace radmesh
