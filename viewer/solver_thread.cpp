#include "viewer/solver_thread.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include "solver/meshing/meshing.h"

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

}  // namespace

struct SolverThread::Run {
  SolveSetup setup;
  std::uint64_t generation = 0;
  std::unique_ptr<ProgressiveSolver> solver;
  std::shared_ptr<const DisplayMesh> mesh;
  SceneSummary summary;
  std::vector<ConvergencePoint> curve;
  std::shared_ptr<const MeshShotStats> lastMeshShot;  // the last one there was (cache hits have none)
  std::shared_ptr<const ItemBuffer> itemBuffer;
  int itemBufferShooter = -1;
  Clock::time_point itemBufferTime{};
};

SolverThread::SolverThread(Scene scene, const SolveSetup& setup, bool playing)
    : scene_(std::move(scene)), playing_(playing), pendingSetup_(setup) {
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
    enum class Work { Restart, Step, ItemBuffer } work = Work::Step;
    SolveSetup setup;
    std::uint64_t generation = 0;
    {
      std::unique_lock lock(mutex_);
      // Paused, the thread still wakes to show the item buffer of the last shot once it is asked for.
      auto itemBufferMissing = [&] {
        return run && itemBufferWanted_ && lastShooter(*run->solver) != run->itemBufferShooter;
      };
      wake_.wait(lock, [&] {
        const bool canStep = run && !run->solver->done();
        return stop_ || restartPending_ || (canStep && (playing_ || pendingSteps_ > 0)) || itemBufferMissing();
      });
      if (stop_) return;
      if (restartPending_) {
        work = Work::Restart;
        restartPending_ = false;
        setup = pendingSetup_;
        generation = ++generation_;
      } else if (run && !run->solver->done() && (playing_ || pendingSteps_ > 0)) {
        if (pendingSteps_ > 0) --pendingSteps_;
      } else {
        work = Work::ItemBuffer;
      }
    }

    if (work == Work::Restart) {
      run = startRun(setup, generation);
      if (run) publish(*run);
      lastPublish = Clock::now();
      continue;
    }
    if (work == Work::ItemBuffer) {
      refreshItemBuffer(*run, true);
      publish(*run);
      continue;
    }
    try {
      const IterationRecord& record = run->solver->step();
      ConvergencePoint point = run->curve.empty() ? ConvergencePoint{} : run->curve.back();
      point.iteration = record.iteration;
      point.convergence = record.convergence;
      point.hostSeconds += record.seconds;
      point.depthAMax = point.depthBMax = -1;
      if (record.meshShot) point.emulatedSeconds += record.meshShot->emulatedSeconds;
      if (record.meshShot && !record.meshShot->depthAHist.empty()) {  // a shot, not a cache hit
        point.depthAMax = record.meshShot->depthAMax;
        point.depthBMax = record.meshShot->depthBMax;
        run->lastMeshShot = record.meshShot;
      }
      run->curve.push_back(point);
    } catch (const std::exception& e) {
      publishFailure(run->setup, e.what());
      run.reset();
      continue;
    }
    bool moreToDo = false;
    {
      std::lock_guard lock(mutex_);
      moreToDo = (playing_ || pendingSteps_ > 0) && !restartPending_;
    }
    // While iterating, publish at the UI's pace; the last iteration before a pause always.
    const bool finished = !moreToDo || run->solver->done();
    if (finished || Clock::now() - lastPublish >= kPublishInterval) {
      refreshItemBuffer(*run, finished);
      publish(*run);
      lastPublish = Clock::now();
    }
  }
}

std::unique_ptr<SolverThread::Run> SolverThread::startRun(const SolveSetup& setup, std::uint64_t generation) {
  try {
    auto run = std::make_unique<Run>();
    run->setup = setup;
    run->generation = generation;
    std::vector<Patch> patches = meshScene(scene_, setup.cellM);
    run->summary = summarizeScene(scene_, patches, setup.cellM);
    run->solver = std::make_unique<ProgressiveSolver>(scene_, std::move(patches), setup.options);
    run->mesh = std::make_shared<const DisplayMesh>(buildDisplayMesh(run->solver->patches()));
    return run;
  } catch (const std::exception& e) {
    publishFailure(setup, e.what());
    return nullptr;
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
  snapshot->vertexB = vertexRadiosity(*run.mesh, run.solver->displayRadiosity());
  const auto& history = run.solver->history();
  if (!history.empty()) {
    snapshot->lastShooters = history.back().shooters;
    snapshot->lastCapturedFraction = history.back().capturedFraction;
  }
  snapshot->lastMeshShot = run.lastMeshShot;
  snapshot->itemBuffer = run.itemBuffer;
  snapshot->itemBufferShooter = run.itemBufferShooter;
  snapshot->curve = run.curve;
  snapshot->ledger = run.solver->ledger();
  snapshot->done = run.solver->done();
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
