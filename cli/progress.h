#pragma once
// Progress of a long solve: one line per iteration, or a single redrawn bar on a terminal.
#include <cstdio>

#include "solver/radiosity/progressive_solver.h"

namespace radmesh::cli {

class Progress {
 public:
  explicit Progress(double until, std::FILE* out = stdout);
  void report(const IterationRecord& record, double elapsedSeconds);
  void finish();  // ends the bar's line on a terminal

 private:
  double until_;
  std::FILE* out_;
  bool terminal_;
  double lastDrawSeconds_ = -1.0;
};

}  // namespace radmesh::cli
