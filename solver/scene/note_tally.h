#pragma once
// Notes of a few kinds that a model may repeat hundreds of times (every open edge of a table top
// is a boundary loop): told once per kind, the first in full and how many more like it, in the
// order the kinds first came.
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace radmesh {

class NoteTally {
 public:
  void add(const std::string& kind, std::string message) {
    for (Kind& k : kinds_)
      if (k.name == kind) {
        ++k.more;
        return;
      }
    kinds_.push_back({kind, std::move(message), 0});
  }
  std::vector<std::string> lines() const {
    std::vector<std::string> out;
    for (const Kind& k : kinds_)
      out.push_back(k.more == 0 ? k.first : fmt::format("{} (and {} more like it)", k.first, k.more));
    return out;
  }

 private:
  struct Kind {
    std::string name;
    std::string first;
    int more = 0;
  };
  std::vector<Kind> kinds_;
};

}  // namespace radmesh
