#include "cli/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <string>

namespace radmesh::cli {

Progress::Progress(double until, std::FILE* out) : until_(until), out_(out), terminal_(isatty(fileno(out)) != 0) {}

void Progress::report(const IterationRecord& r, double elapsed) {
  const double rate = elapsed > 0.0 ? r.iteration / elapsed : 0.0;
  if (!terminal_) {
    fmt::print(out_,
               "iteration {:5d}  shooter {:6d}  shot {:11.5g} W  C {:6.2f}%  unshot {:6.2f}%  {:8.3f} ms  {:8.1f} it/s\n",
               r.iteration, r.shooters.empty() ? -1 : r.shooters.front(), r.shotPowerW, 100.0 * r.convergence,
               100.0 * r.ledger.unshotFraction(), 1e3 * r.seconds, rate);
    return;
  }
  // A terminal gets a bar redrawn at most 20 times a second.
  if (elapsed - lastDrawSeconds_ < 0.05) return;
  lastDrawSeconds_ = elapsed;
  const int width = 30;
  const int filled = static_cast<int>(width * std::clamp(r.convergence / until_, 0.0, 1.0));
  fmt::print(out_, "\r[{}{}] C {:6.2f}% of {:.0f}%  unshot {:.2f}%  iteration {}  {:.1f} it/s ",
             std::string(filled, '#'), std::string(width - filled, '.'), 100.0 * r.convergence, 100.0 * until_,
             100.0 * r.ledger.unshotFraction(), r.iteration, rate);
  std::fflush(out_);
}

void Progress::finish() {
  if (terminal_) fmt::print(out_, "\n");
}

}  // namespace radmesh::cli
