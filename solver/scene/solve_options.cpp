#include "solver/scene/solve_options.h"

#include <fmt/format.h>

#include <sys/resource.h>  // getrlimit: ulimit -v
#include <unistd.h>        // sysconf: the machine's memory

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

std::string number(double value) { return fmt::format("{}", value); }  // shortest exact form

constexpr int kMaxPeSide = 1024;
constexpr int kMaxPeMemoryKb = 1024 * 1024;  // 1 GB a PE

bool powerOfTwoSide(int side) { return side >= 2 && side <= kMaxPeSide && (side & (side - 1)) == 0; }

void validateMachine(const PeMachine& m) {
  if (!powerOfTwoSide(m.cols) || !powerOfTwoSide(m.rows))
    throw OptionError("--pe-grid " + peGridText(m) + " is not a mesh the machine can sort on: give COLSxROWS with "
                      "powers of two from 2 to " + std::to_string(kMaxPeSide) + ", e.g. 64x64 (the MP-1) or 128x128");
  if (m.memoryKb < 1 || m.memoryKb > kMaxPeMemoryKb)
    throw OptionError("--pe-memory " + std::to_string(m.memoryKb) + " is out of range: give each PE's memory in KB "
                      "from 1 to " + std::to_string(kMaxPeMemoryKb) + ", e.g. 16 (the MP-1's)");
}

}  // namespace

void checkMinElement(double minElementM) {
  if (!(std::isfinite(minElementM) && minElementM >= 0.0))
    throw OptionError("--min-element " + number(minElementM) +
                      " is out of range: give the longest element edge in metres, e.g. 0.1 (0: every patch cut into four, or with "
                      "--subdivide adaptive, a quarter of the cell)");
}

void checkResolution(int resolution, const std::string& option) {
  if (resolution < 16 || resolution > 2048)
    throw OptionError(option + " " + std::to_string(resolution) +
                      " is out of range: give N from 16 to 2048 (the projection surface is N x N)");
}

void refuseFlagsThatShapeNothing(const std::vector<std::string>& given, const SolveOptions& o, bool cellsOn) {
  for (const std::string& flag : given) {
    const auto unused = [&](const std::string& shapes, const std::string& setting, const std::string& add) {
      return OptionError(fmt::format("{} shapes {}, and {}: add {}, or leave {} out", flag, shapes, setting, add, flag));
    };
    const std::string subdivide = std::string("--subdivide is ") + toString(o.subdivide);
    if ((flag == "--min-element" || flag == "--element-rows") && o.subdivide == Subdivide::Off)
      throw unused("the elements", subdivide, "--subdivide uniform or adaptive (docs/accuracy.md)");
    if (flag.starts_with("--split-") && o.subdivide != Subdivide::Adaptive)
      throw unused("adaptive elements", subdivide, "--subdivide adaptive (docs/accuracy.md)");
    if (flag == "--ratio" && o.projection != Projection::Plane)
      throw unused("the single plane", std::string("--projection is ") + toString(o.projection), "--projection plane");
    if ((flag == "--mapping" || flag == "--pe-grid" || flag == "--pe-memory") && o.backend != Backend::Mesh)
      throw unused("the emulated MP-1", std::string("--backend is ") + toString(o.backend), "--backend mesh");
    if ((flag == "--exchange-shots" || flag == "--portal-bins") && !cellsOn)
      throw unused("a cells solve", "--cells is off", "--cells auto");
  }
}

void validateOptions(const SolveOptions& o) {
  checkResolution(o.resolution, "--resolution");
  if (!std::isfinite(o.ratio) || o.ratio <= 0.0)
    throw OptionError("--ratio " + number(o.ratio) +
                      " is not a finite, positive number: give the single plane's half-side at "
                      "height 1, e.g. 3 (the paper's)");
  if (o.shooters < 1)
    throw OptionError("--shooters " + std::to_string(o.shooters) +
                      " is out of range: give at least 1 shooter per iteration");
  if (!std::isfinite(o.until) || o.until <= 0.0 || o.until > 1.0)
    throw OptionError("--until " + number(o.until) +
                      " is out of range: give a convergence in (0, 1], e.g. 0.95");
  if (!std::isfinite(o.untilUnshot) || o.untilUnshot < 0.0 || o.untilUnshot >= 1.0)
    throw OptionError("--until-unshot " + number(o.untilUnshot) +
                      " is out of range: give a fraction of the emitted power in [0, 1), e.g. 0.01 (0: off)");
  if (o.maxIterations < 1)
    throw OptionError("--max-iterations " + std::to_string(o.maxIterations) +
                      " is out of range: give at least 1");
  if (o.threads < 0)
    throw OptionError("--threads " + std::to_string(o.threads) +
                      " is out of range: give 0 (every core) or a positive count");
  validateMachine(o.machine);
  checkMinElement(o.minElementM);
  if (o.backend == Backend::Mesh && o.projection != Projection::Plane)
    throw OptionError(std::string("--backend mesh runs the paper's single plane; --projection ") +
                      toString(o.projection) + " is native only: use --projection plane or --backend native");
  if (o.elementRows == ElementRows::Share && o.backend == Backend::Mesh)
    throw OptionError("--element-rows share is the native back end's: the mesh back end z-buffers every element on "
                      "its PEs, as the paper's machine does; give --element-rows rasterise (or auto), or --backend native");
  if (o.meshTransport && o.backend != Backend::Mesh)
    throw OptionError("--distributed splits the mesh back end's machine over processes: give --backend mesh (or "
                      "--cells auto, which splits the cells)");
  if (!(std::isfinite(o.splitContrast) && o.splitContrast > 0.0))
    throw OptionError("--split-contrast " + number(o.splitContrast) +
                      " is out of range: give a fraction of the brightest element's radiosity above 0, e.g. 0.1");
}

void checkAdaptiveMinElement(const SolveOptions& o) {
  if (o.subdivide == Subdivide::Adaptive && !(o.minElementM > 0.0))
    throw OptionError("--subdivide adaptive splits elements down to --min-element, so it needs one above 0: give "
                      "about a quarter of the meshing cell, e.g. --min-element 0.25 for --cell 1 (radmesh solve "
                      "takes that where none is given)");
}

bool defaultMinElement(SolveOptions& o, double cellM) {
  if (o.subdivide != Subdivide::Adaptive || o.minElementM != 0.0) return false;
  o.minElementM = 0.25 * cellM;
  return true;
}

std::string quarterMinElementNote(double minElementM) {
  return fmt::format("min element {:.4g} m, a quarter of the cell (--min-element sets it)", minElementM);
}

void parsePeGrid(const std::string& text, PeMachine& machine) {
  auto whole = [&](std::string_view part, int& value) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return !part.empty() && error == std::errc() && end == part.data() + part.size();
  };
  const std::string_view view = text;
  const std::size_t x = view.find('x');
  PeMachine parsed = machine;
  if (x == std::string_view::npos || !whole(view.substr(0, x), parsed.cols) || !whole(view.substr(x + 1), parsed.rows))
    throw OptionError("--pe-grid '" + text + "' is not COLSxROWS: give the PE columns and rows as powers of two "
                      "joined by x, e.g. 128x128");
  machine = parsed;
}

std::string peGridText(const PeMachine& machine) {
  return std::to_string(machine.cols) + "x" + std::to_string(machine.rows);
}

const char* toString(Projection projection) {
  switch (projection) {
    case Projection::Plane: return "plane";
    case Projection::Hemicube: return "hemicube";
    case Projection::Analytic: return "analytic";
  }
  return "?";
}

std::string projectionText(Projection projection, int resolution) {
  if (projection == Projection::Analytic) return toString(projection);
  return fmt::format("{} {}x{}", toString(projection), resolution, resolution);
}

const char* toString(Backend backend) {
  switch (backend) {
    case Backend::Native: return "native";
    case Backend::Mesh: return "mesh";
  }
  return "?";
}

Projection parseProjection(const std::string& text) {
  for (Projection p : {Projection::Plane, Projection::Hemicube, Projection::Analytic})
    if (text == toString(p)) return p;
  throw OptionError("--projection '" + text + "' is unknown: give plane, hemicube or analytic");
}

Backend parseBackend(const std::string& text) {
  for (Backend b : {Backend::Native, Backend::Mesh})
    if (text == toString(b)) return b;
  throw OptionError("--backend '" + text + "' is unknown: give native or mesh");
}

bool parseCells(const std::string& text) {
  if (text != "auto" && text != "off")
    throw OptionError("--cells '" + text + "' is unknown: give auto (find the rooms and solve them cell by cell) or off");
  return text == "auto";
}

void applyPreset(Preset preset, SolveOptions& o) {
  const bool paper = preset == Preset::Paper, elements = preset == Preset::Elements;
  o.projection = paper ? Projection::Plane : Projection::Hemicube;
  o.resolution = paper ? 128 : 256;
  o.ratio = 3.0;
  o.shooters = 1;
  o.until = paper ? 0.95 : 1.0;  // the others stop on the unshot power alone
  o.untilUnshot = paper ? 0.0 : 0.01;
  o.subdivide = elements ? Subdivide::Uniform : Subdivide::Off;
}

std::size_t usableMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageBytes = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageBytes <= 0) return 0;
  std::size_t usable = static_cast<std::size_t>(pages) * static_cast<std::size_t>(pageBytes);
  // A cgroup's cap (v2, then v1): "max", or a figure past the machine's, when there is none.
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::size_t cap = 0;
    if (std::ifstream in(path); in >> cap && cap > 0) usable = std::min(usable, cap);
  }
  if (rlimit limit{}; getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    usable = std::min(usable, static_cast<std::size_t>(limit.rlim_cur));
  return usable;
}

std::size_t defaultFormFactorCacheBytes() {
  constexpr std::size_t kBudget = std::size_t{1} << 30;
  const std::size_t memory = usableMemoryBytes();
  if (memory == 0) return kBudget;  // unknown: the machine is taken to have 4 GiB
  return std::min(kBudget, memory / 4);
}

std::size_t formFactorCacheBytes(Backend backend, std::optional<double> givenMb) {
  if (!givenMb) return backend == Backend::Native ? defaultFormFactorCacheBytes() : 0;
  return static_cast<std::size_t>(checkedCacheMb(*givenMb) * 1024 * 1024);
}

double checkedCacheMb(double givenMb) {
  if (!(givenMb >= 0.0 && givenMb < 1e6)) throw OptionError("--cache-mb must be a size in MiB from 0 to 1e6");
  return givenMb;
}

double elementsPresetCell(double sceneCellM) {
  const double cell = kElementsCellScale * sceneCellM;
  const double unit = std::pow(10.0, std::floor(std::log10(cell)) - 1.0);
  return std::round(cell / unit) * unit;
}

const char* toString(Preset preset) {
  switch (preset) {
    case Preset::Bake: return "bake";
    case Preset::Paper: return "paper";
    case Preset::Elements: return "elements";
  }
  return "?";
}

Preset parsePreset(const std::string& text) {
  for (Preset p : {Preset::Bake, Preset::Paper, Preset::Elements})
    if (text == toString(p)) return p;
  throw OptionError("--preset '" + text + "' is unknown: give bake (hemicube 256, until 1 % unshot), paper "
                    "(single plane 128, ratio 3, until C = 0.95) or elements (the bake, but 1 m patches shoot and "
                    "0.25 m elements receive, on a room-sized model)");
}

const char* toString(EffectsMode mode) { return mode == EffectsMode::All ? "all" : "auto"; }

EffectsMode parseEffects(const std::string& text) {
  for (EffectsMode m : {EffectsMode::Auto, EffectsMode::All})
    if (text == toString(m)) return m;
  throw OptionError("--effects must be 'auto' (simulate only what the scene calls for) or 'all', not '" + text + "'");
}

const char* toString(Subdivide subdivide) {
  switch (subdivide) {
    case Subdivide::Off: return "off";
    case Subdivide::Uniform: return "uniform";
    case Subdivide::Adaptive: return "adaptive";
  }
  return "?";
}

Subdivide parseSubdivide(const std::string& text) {
  for (Subdivide s : {Subdivide::Off, Subdivide::Uniform, Subdivide::Adaptive})
    if (text == toString(s)) return s;
  throw OptionError("--subdivide '" + text + "' is unknown: give off (patches receive), uniform (patches shoot, "
                    "elements of at most --min-element receive) or adaptive (elements split where the light changes)");
}

const char* toString(ElementRows rows) {
  switch (rows) {
    case ElementRows::Auto: return "auto";
    case ElementRows::Rasterise: return "rasterise";
    case ElementRows::Share: return "share";
  }
  return "?";
}

ElementRows parseElementRows(const std::string& text) {
  for (ElementRows r : {ElementRows::Auto, ElementRows::Rasterise, ElementRows::Share})
    if (text == toString(r)) return r;
  throw OptionError("--element-rows '" + text + "' is unknown: give share (patches on the item buffer, each one's "
                    "form factor shared among its elements), rasterise (every element on the item buffer) or auto");
}

ElementRows resolvedElementRows(const SolveOptions& options) {
  const bool shares = options.subdivide != Subdivide::Off && options.projection != Projection::Analytic &&
                      options.backend == Backend::Native && options.elementRows != ElementRows::Rasterise;
  return shares ? ElementRows::Share : ElementRows::Rasterise;
}

}  // namespace radmesh
