// Portal power in a message between processes (cell_ranks.h): the runs of bins carrying light, or
// the full bins where those are shorter.
#include <fmt/format.h>

#include <stdexcept>

#include "solver/radiosity/cell_ranks.h"

namespace radmesh {

CellTraffic operator-(const CellTraffic& after, const CellTraffic& before) {
  return {after.messages - before.messages, after.bytes - before.bytes, after.gathers - before.gathers,
          after.gatherBytes - before.gatherBytes, after.waitSeconds - before.waitSeconds};
}

std::size_t appendPortalRuns(std::span<const Rgb> bins, std::size_t link, std::vector<double>& message) {
  const std::size_t start = message.size();
  for (std::size_t b = 0; b < bins.size();) {
    if (bins[b] == Rgb(0.0)) {
      ++b;
      continue;
    }
    std::size_t end = b;
    while (end < bins.size() && bins[end] != Rgb(0.0)) ++end;
    message.insert(message.end(), {static_cast<double>(link * bins.size() + b), static_cast<double>(end - b)});
    for (; b < end; ++b) message.insert(message.end(), {bins[b].r, bins[b].g, bins[b].b});
  }
  return message.size() - start;
}

std::size_t portalMessageDoubles(std::size_t runDoubles, std::size_t fullBins) {
  return runDoubles < 3 * fullBins ? runDoubles : 3 * fullBins;
}

std::vector<double> portalMessage(std::vector<double> runs, std::span<const Rgb> fullBins) {
  if (runs.size() == portalMessageDoubles(runs.size(), fullBins.size())) return runs;
  std::vector<double> full;
  for (const Rgb& bin : fullBins) full.insert(full.end(), {bin.r, bin.g, bin.b});
  return full;
}

std::vector<Rgb> readPortalMessage(const std::vector<double>& message, std::size_t links, std::size_t bins) {
  std::vector<Rgb> out(links * bins, Rgb(0.0));
  if (message.size() == 3 * out.size()) {  // the full bins
    for (std::size_t b = 0; b < out.size(); ++b) out[b] = Rgb(message[3 * b], message[3 * b + 1], message[3 * b + 2]);
    return out;
  }
  for (std::size_t at = 0; at < message.size();) {
    // The position and length are whole numbers below 2^53, exact as doubles.
    const double first = message[at], length = at + 1 < message.size() ? message[at + 1] : -1.0;
    const bool fits = first >= 0.0 && length >= 1.0 && first + length <= static_cast<double>(out.size()) &&
                      at + 2 + 3 * static_cast<std::size_t>(length) <= message.size();
    if (!fits)
      throw std::runtime_error(fmt::format("a message of portal power holds a run ({}, {}) at double {} that does not "
                                           "fit its {} links of {} bins ({} doubles)",
                                           first, length, at, links, bins, message.size()));
    at += 2;
    for (std::size_t b = static_cast<std::size_t>(first); b < static_cast<std::size_t>(first + length); ++b, at += 3)
      out[b] = Rgb(message[at], message[at + 1], message[at + 2]);
  }
  return out;
}

}  // namespace radmesh
