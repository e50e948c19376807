#pragma once
// The progressive solver (or, with SolveSetup::cells, the cells solver) on its own thread. The UI sends commands (play, pause, step, restart)
// and reads the newest published snapshot; neither ever waits for an iteration to finish.
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "solver/scene/scene.h"
#include "viewer/solver_snapshot.h"

namespace radmesh {

class SolverThread {
 public:
  // Meshes and starts solving at once (playing) or waits for a command (paused), or takes `steps`
  // iterations and pauses; with a checkpoint (solver/radiosity/checkpoint.h), the first solve goes
  // on from it, made here on the caller's thread: a checkpoint that cannot be read or is of another
  // solve throws its SceneError (as radmesh solve --resume refuses it) before anything runs.
  // `eye`, where the camera starts (setEye), lets a resumed cells solve know its focus from the start.
  SolverThread(Scene scene, const SolveSetup& setup, bool playing, std::string resumePath = {}, int steps = 0,
               std::optional<Vec3> eye = std::nullopt);
  ~SolverThread();  // stops after the iteration under way and joins
  SolverThread(const SolverThread&) = delete;
  SolverThread& operator=(const SolverThread&) = delete;

  void play();
  void pause();               // also cancels pending steps
  // This many more iterations (with cells: rounds), then pause; also past the stopping rule.
  void step(int iterations);
  // Changes the stopping rule of the solve under way (and of later restarts), without restarting
  // it: a stricter rule lets a stopped solve play on. Throws OptionError on values out of range.
  void setStoppingRule(double until, double untilUnshot);
  void restart(const SolveSetup& setup);  // remesh and solve from scratch, keeping play/pause
  // Saves the solve to a checkpoint after the iteration under way; the snapshots' checkpointMessage
  // then says where, or why not.
  void saveCheckpoint(const std::string& path);
  // Where the camera's eye is: a cells solve solves its cell first, and follows it from round to
  // round. Until it is given, every cell shoots alike.
  void setEye(const Vec3& eye);
  // Whether snapshots should carry the last shooter's item buffer (it costs a projection).
  void setItemBufferWanted(bool wanted);

  // The newest snapshot; never null (the first one has no mesh yet).
  std::shared_ptr<const SolverSnapshot> latest() const;

 private:
  struct Run;  // the solver and what the thread accumulates across its iterations (solver_run.h)
  void loop();
  // With a resume path, goes on from that checkpoint. Throws what meshing, the solver or the
  // checkpoint refuses.
  std::unique_ptr<Run> makeRun(const SolveSetup& setup, std::uint64_t generation, const std::string& resumePath,
                               const std::optional<Vec3>& eye);
  // makeRun on the solver thread: null, its failure published, when it throws.
  std::unique_ptr<Run> startRun(const SolveSetup& setup, std::uint64_t generation, const std::optional<Vec3>& eye);
  void save(Run& run, const std::string& path);
  void refreshItemBuffer(Run& run, bool finished);
  static std::shared_ptr<const CellsProgress> cellsProgress(const Run& run);
  void publish(const Run& run);
  void publishFailure(const SolveSetup& setup, const std::exception& error);

  const Scene scene_;
  mutable std::mutex mutex_;  // guards everything below, up to thread_
  std::condition_variable wake_;
  bool stop_ = false;
  bool playing_ = false;
  int pendingSteps_ = 0;
  bool restartPending_ = true;
  bool stoppingRulePending_ = false;
  bool itemBufferWanted_ = false;
  std::optional<Vec3> eye_;
  SolveSetup pendingSetup_;
  std::unique_ptr<Run> resumed_;  // the first run, made from the checkpoint by the constructor
  std::optional<std::string> pendingCheckpoint_;  // where to save, once the iteration under way is done
  std::uint64_t generation_ = 0;
  std::shared_ptr<const SolverSnapshot> latest_;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace radmesh
