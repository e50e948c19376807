#include "viewer/solver_thread.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <optional>
#include <sys/resource.h>
#include <unistd.h>
#include <utility>

#include "solver/scene/scene_error.h"
#include "viewer/solver_run.h"

namespace radmesh {

namespace {

using Clock = std::chrono::steady_clock;

// Publishing costs a pass over every vertex; while playing, the UI needs no more than this.
constexpr auto kPublishInterval = std::chrono::milliseconds(40);
// The solver thread's nice value, above the drawing thread's 0 (Linux's nice is per thread).
constexpr int kSolverNice = 10;
// An item buffer costs a projection of every patch: while playing, one now and then is enough.
constexpr auto kItemBufferInterval = std::chrono::milliseconds(500);

}  // namespace

SolverThread::SolverThread(Scene scene, const SolveSetup& setup, bool playing, std::string resumePath, int steps,
                           std::optional<Vec3> eye)
    : scene_(std::move(scene)),
      playing_(playing),
      pendingSteps_(std::max(0, steps)),
      eye_(eye),
      pendingSetup_(setup) {
  if (!resumePath.empty()) {
    resumed_ = makeRun(setup, ++generation_, resumePath, eye_);
    restartPending_ = false;
  }
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
  std::unique_ptr<Run> run = std::move(resumed_);
  if (run) publish(*run);
  Clock::time_point lastPublish{};
  for (;;) {
    enum class Work { Restart, StoppingRule, Checkpoint, Step, ItemBuffer } work = Work::Step;
    SolveSetup setup;
    std::string checkpointPath;
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
        return stop_ || restartPending_ || (run && stoppingRulePending_) || (run && pendingCheckpoint_) ||
               canStep() || itemBufferMissing();
      });
      if (stop_) return;
      eye = eye_;
      if (restartPending_) {
        work = Work::Restart;
        restartPending_ = false;
        stoppingRulePending_ = false;  // the new setup carries it
        setup = pendingSetup_;
        generation = ++generation_;
      } else if (stoppingRulePending_) {
        work = Work::StoppingRule;
        stoppingRulePending_ = false;
        setup = pendingSetup_;
      } else if (run && pendingCheckpoint_) {
        work = Work::Checkpoint;
        checkpointPath = *std::exchange(pendingCheckpoint_, std::nullopt);
      } else if (canStep()) {
        if (pendingSteps_ > 0) --pendingSteps_;
      } else {
        work = Work::ItemBuffer;
      }
    }

    if (work == Work::Restart) {
      run = startRun(setup, generation, eye);
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
      publishFailure(run->setup, e);
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
      run->remeshIfSplit();
      refreshItemBuffer(*run, finished);
      publish(*run);
      lastPublish = Clock::now();
    }
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

}  // namespace radmesh
