#include "solver/io/mgf_transform.h"

#include <cmath>
#include <numbers>

#include "solver/io/mgf_error.h"
#include "solver/io/mgf_reader.h"

namespace radmesh {

namespace {

MgfAffine rotation(int axis, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(a);
  const double s = std::sin(a);
  const int i = (axis + 1) % 3;  // the two coordinates the rotation mixes, in right-handed order
  const int j = (axis + 2) % 3;
  MgfAffine r;
  r.linear[i][i] = c;  // glm is column-major: linear[column][row]
  r.linear[i][j] = s;
  r.linear[j][i] = -s;
  r.linear[j][j] = c;
  return r;
}

// One run of arguments with how often it applies: once, -i N times, or 0..N-1 times for -a N.
struct Segment {
  MgfAffine transform;
  int count = 1;
  bool array = false;
};

std::vector<Segment> parseSegments(const std::vector<std::string>& args) {
  std::vector<Segment> segments(1);
  size_t repeats = 0;  // every -i applies its transform that many times: bounded as instances are
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    // The next argument, a number the flag `a` takes (a -t takes three: each is named with -t).
    const auto number = [&](size_t& next, const std::string& what) {
      if (++next >= args.size()) throw MgfError(a + " is missing its " + what, "give " + a + " a " + what);
      return parseMgfNumber(args[next], a + " " + what);
    };
    MgfAffine step;
    if (a == "-t") {
      const double x = number(k, "dx");
      const double y = number(k, "dy");
      step.offset = {x, y, number(k, "dz")};
    } else if (a == "-rx" || a == "-ry" || a == "-rz") {
      step = rotation(a[2] - 'x', number(k, "angle in degrees"));
    } else if (a == "-s") {
      const double s = number(k, "scale factor");
      if (s == 0.0) throw MgfError("-s 0 collapses everything to a point", "give a non-zero scale");
      step.linear = glm::dmat3(s);
    } else if (a == "-mx" || a == "-my" || a == "-mz") {
      step.linear[a[2] - 'x'][a[2] - 'x'] = -1.0;
    } else if (a == "-i" || a == "-a") {
      if (k + 1 >= args.size())
        throw MgfError(a + " is missing its count", "write " + a + " N before the arguments to repeat");
      const int n = parseMgfCount(args[++k], a + " count", a == "-a" ? 1 : 0);
      if (static_cast<size_t>(n) > kMaxMgfInstances)
        throw MgfError(a + " " + args[k] + " is more than " + std::to_string(kMaxMgfInstances),
                       "use a smaller count");
      if (a == "-i" && (repeats += static_cast<size_t>(n)) > kMaxMgfInstances)
        throw MgfError("the -i counts of this transform add up to more than " + std::to_string(kMaxMgfInstances),
                       "use smaller -i counts");
      segments.push_back({MgfAffine{}, n, a == "-a"});
      continue;
    } else {
      throw MgfError("unknown transform argument '" + a + "'",
                     "use -t, -rx, -ry, -rz, -s, -mx, -my, -mz, -i or -a");
    }
    segments.back().transform = segments.back().transform.then(step);
  }
  return segments;
}

}  // namespace

std::vector<MgfAffine> mgfTransformInstances(const std::vector<std::string>& args) {
  std::vector<MgfAffine> instances(1);
  for (const Segment& s : parseSegments(args)) {
    if (!s.array) {
      MgfAffine repeated;
      for (int k = 0; k < s.count; ++k) repeated = repeated.then(s.transform);
      for (MgfAffine& t : instances) t = t.then(repeated);
      continue;
    }
    if (instances.size() * static_cast<size_t>(s.count) > kMaxMgfInstances)
      throw MgfError("the arrays make more than " + std::to_string(kMaxMgfInstances) + " instances",
                     "use smaller -a counts");
    std::vector<MgfAffine> grown;
    for (const MgfAffine& t : instances) {
      MgfAffine repeated;  // s.transform applied k times
      for (int k = 0; k < s.count; ++k, repeated = repeated.then(s.transform))
        grown.push_back(t.then(repeated));
    }
    instances = std::move(grown);
  }
  return instances;
}

}  // namespace radmesh
