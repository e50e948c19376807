#include "viewer/solver_thread.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "solver/meshing/meshing.h"
#include "solver/radiosity/checkpoint.h"

namespace radmesh {

namespace {

using Clock = std::chrono::steady_clock;

// Publishing costs a pass over every vertex; while playing, the UI needs no more than this.
constexpr auto kPublishInterval = std::chrono::milliseconds(40);
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
  std::unique_ptr<ProgressiveSolver> solver;
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
    pendingSetup_.options = checked;
    stoppingRulePending_ = true;
  }
  wake_.notify_all();
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
  std::unique_ptr<Run> run;
  Clock::time_point lastPublish{};
  for (;;) {
    enum class Work { Restart, StoppingRule, Checkpoint, Step, ItemBuffer } work = Work::Step;
    SolveSetup setup;
    std::string resumePath, checkpointPath;
    std::uint64_t generation = 0;
    {
      std::unique_lock lock(mutex_);
      // Paused, the thread still wakes to show the item buffer of the last shot once it is asked for.
      auto itemBufferMissing = [&] {
        return run && itemBufferWanted_ && lastShooter(*run->solver) != run->itemBufferShooter;
      };
      // Playing stops at the stopping rule; a step asked for goes past it, until nothing is left.
      auto canStep = [&] {
        return run && ((playing_ && !run->solver->done()) || (pendingSteps_ > 0 && !run->solver->exhausted()));
      };
      wake_.wait(lock, [&] {
        return stop_ || restartPending_ || (run && stoppingRulePending_) || (run && !pendingCheckpoint_.empty()) ||
               canStep() || itemBufferMissing();
      });
      if (stop_) return;
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
      run = startRun(setup, generation, resumePath);
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
      run->solver->setStoppingRule(setup.options.until, setup.options.untilUnshot);  // validated by the caller
      publish(*run);
      continue;
    }
    if (work == Work::ItemBuffer) {
      refreshItemBuffer(*run, true);
      publish(*run);
      continue;
    }
    try {
      run->add(run->solver->step());
    } catch (const std::exception& e) {
      publishFailure(run->setup, e.what());
      run.reset();
      continue;
    }
    bool moreToDo = false;
    {
      std::lock_guard lock(mutex_);
      moreToDo = ((playing_ && !run->solver->done()) || pendingSteps_ > 0) && !restartPending_;
    }
    // While iterating, publish at the UI's pace; the last iteration before a pause always.
    const bool finished = !moreToDo || run->solver->exhausted();
    if (finished || Clock::now() - lastPublish >= kPublishInterval) {
      refreshItemBuffer(*run, finished);
      publish(*run);
      lastPublish = Clock::now();
    }
  }
}

std::unique_ptr<SolverThread::Run> SolverThread::startRun(const SolveSetup& setup, std::uint64_t generation,
                                                         const std::string& resumePath) {
  try {
    auto run = std::make_unique<Run>();
    run->setup = setup;
    run->generation = generation;
    std::vector<Patch> patches = meshScene(scene_, setup.cellM);
    run->summary = summarizeScene(scene_, patches, setup.cellM);
    run->solver = std::make_unique<ProgressiveSolver>(scene_, std::move(patches), setup.options);
    if (!resumePath.empty()) {
      resumeFromCheckpoint(resumePath, *run->solver);
      for (const IterationRecord& record : run->solver->history()) run->add(record);
      run->checkpointMessage = "resumed from " + resumePath;
    }
    run->mesh = std::make_shared<const DisplayMesh>(buildDisplayMesh(run->solver->elements()));
    return run;
  } catch (const std::exception& e) {
    publishFailure(setup, e.what());
    return nullptr;
  }
}

void SolverThread::save(Run& run, const std::string& path) {
  try {
    writeCheckpoint(path, *run.solver);
    run.checkpointMessage = "saved " + path + " after iteration " + std::to_string(run.solver->history().size());
  } catch (const std::exception& e) {
    run.checkpointMessage = e.what();
  }
}

void SolverThread::refreshItemBuffer(Run& run, bool finished) {
  const int shooter = lastShooter(*run.solver);
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

void SolverThread::publish(const Run& run) {
  auto snapshot = std::make_shared<SolverSnapshot>();
  snapshot->generation = run.generation;
  snapshot->setup = run.setup;
  snapshot->mesh = run.mesh;
  snapshot->summary = run.summary;
  snapshot->effects = run.solver->effectsPlan().effects;
  snapshot->vertexB = vertexRadiosity(*run.mesh, run.solver->displayElementRadiosity());
  const auto& history = run.solver->history();
  if (!history.empty()) {
    snapshot->lastShooters = history.back().shooters;
    snapshot->lastShooterElements = run.solver->elementsOf(snapshot->lastShooters);
    snapshot->lastCapturedFraction = history.back().capturedFraction;
  }
  snapshot->lastShotStats = run.lastShotStats;
  snapshot->itemBuffer = run.itemBuffer;
  snapshot->itemBufferShooter = run.itemBufferShooter;
  snapshot->curve = run.curve;
  snapshot->ledger = run.solver->ledger();
  snapshot->done = run.solver->done();
  snapshot->checkpointMessage = run.checkpointMessage;
  snapshot->exhausted = run.solver->exhausted();
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
