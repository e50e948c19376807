#include "solver/io/ies_photometry.h"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

constexpr double kFootM = 0.3048;
constexpr double kPointOpeningM = 0.01;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// The numbers after the TILT line, read one by one with a name for the error that names them.
class Numbers {
 public:
  Numbers(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}
  double next(const std::string& what) {
    std::string word;
    if (!(in_ >> word))
      throw SceneError(file_, what, "is missing: the file ends early (truncated?)", "restore the end of the file");
    try {
      size_t used = 0;
      const double value = std::stod(word, &used);
      if (used == word.size() && std::isfinite(value)) return value;
    } catch (const std::exception&) {
    }
    throw SceneError(file_, what, "'" + word + "' is not a finite number", "give it as a decimal number");
  }
  int count(const std::string& what, int atLeast) {
    const double value = next(what);
    if (value != std::floor(value) || value < atLeast || value > 10000)
      throw SceneError(file_, what, fmt::format("{} is not a whole number from {} to 10000", value, atLeast),
                       "correct the count");
    return static_cast<int>(value);
  }
  std::vector<double> list(int n, const std::string& what) {
    std::vector<double> out;
    for (int i = 0; i < n; ++i) out.push_back(next(fmt::format("{} {}", what, i + 1)));
    return out;
  }

 private:
  std::istream& in_;
  std::string file_;
};

// Integral of I(theta) sin(theta) from a to b (radians), I linear from ia to ib.
double segmentFlux(double a, double ia, double b, double ib) {
  const double slope = (ib - ia) / (b - a);
  return ia * (std::cos(a) - std::cos(b)) + slope * (std::sin(b) - std::sin(a) - (b - a) * std::cos(b));
}

// Integral of I(theta) sin(theta) over each segment, I linear in theta between the angles given,
// added to `down` below the horizontal (theta < 90 degrees from nadir) and to `up` above it; a
// segment across the horizontal is cut there, at I interpolated.
void integrateVertical(const std::vector<double>& anglesDeg, const std::vector<double>& candela, double& down,
                       double& up) {
  for (size_t k = 0; k + 1 < anglesDeg.size(); ++k) {
    const double a = anglesDeg[k], b = anglesDeg[k + 1];
    if (!(b > a)) continue;  // a repeated angle: a step in I, no width
    if (b <= 90.0) {
      down += segmentFlux(radians(a), candela[k], radians(b), candela[k + 1]);
    } else if (a >= 90.0) {
      up += segmentFlux(radians(a), candela[k], radians(b), candela[k + 1]);
    } else {
      const double horizontal = candela[k] + (candela[k + 1] - candela[k]) * (90.0 - a) / (b - a);
      down += segmentFlux(radians(a), candela[k], radians(90.0), horizontal);
      up += segmentFlux(radians(90.0), horizontal, radians(b), candela[k + 1]);
    }
  }
}

// Throws unless `angles` rise (or repeat: a step) within [low, high] degrees.
void checkAngles(const std::vector<double>& angles, double low, double high, const std::string& file,
                 const std::string& what) {
  for (size_t k = 0; k < angles.size(); ++k)
    if (angles[k] < low || angles[k] > high || (k > 0 && angles[k] < angles[k - 1]))
      throw SceneError(file, fmt::format("{} {}", what, k + 1),
                       fmt::format("is {} degrees: the {}s must rise from {} to at most {} (a count that differs "
                                   "from the list shifts the numbers too)",
                                   angles[k], what, low, high),
                       "correct the angles, or the count before them");
}

}  // namespace

IesLuminaire readIes(const std::string& path, double multiplier) {
  std::ifstream in(path);
  if (!in) throw SceneError(path, "", "cannot be opened", "check that the IES file exists beside the MGF file");
  IesLuminaire lum;
  std::string line;
  bool tiltFound = false;
  while (std::getline(in, line)) {
    if (line.rfind("TILT=", 0) != 0) continue;
    tiltFound = true;
    break;
  }
  if (!tiltFound)
    throw SceneError(path, "TILT", "no TILT= line: this is not an IESNA LM-63 file, or it is truncated",
                     "give MGF's ies entity an LM-63 photometric file");
  std::string tilt = line.substr(5);
  while (!tilt.empty() && std::isspace(static_cast<unsigned char>(tilt.back()))) tilt.pop_back();
  Numbers numbers(in, path);
  if (tilt == "INCLUDE") {
    numbers.next("lamp-to-luminaire geometry");
    const int pairs = numbers.count("number of tilt angles", 0);
    numbers.list(2 * pairs, "tilt value");
    lum.notes.push_back("its lamp tilt factors are not applied (the luminaire is taken as tested)");
  } else if (tilt != "NONE") {
    lum.notes.push_back("its tilt file '" + tilt + "' is not read (the luminaire is taken as tested)");
  }
  numbers.count("number of lamps", 1);
  numbers.next("lumens per lamp");
  const double candelaMultiplier = numbers.next("candela multiplier");
  // A factor of 0 or less would make no light, or light out of negative candela.
  auto positive = [&](double value, const std::string& what) {
    if (!(value > 0.0))
      throw SceneError(path, what, fmt::format("is {}: the luminaire would give no light, or negative light", value),
                       "give it above 0 (1 when it does not apply)");
  };
  positive(candelaMultiplier, "candela multiplier");
  const int vertical = numbers.count("number of vertical angles", 2);
  const int horizontal = numbers.count("number of horizontal angles", 1);
  const int type = numbers.count("photometric type", 1);
  const int units = numbers.count("units type", 1);
  const double width = numbers.next("width"), length = numbers.next("length"), height = numbers.next("height");
  const double ballast = numbers.next("ballast factor");
  const double ballastLamp = numbers.next("ballast-lamp photometric factor");
  numbers.next("input watts");
  positive(ballast, "ballast factor");
  positive(ballastLamp, "ballast-lamp photometric factor");
  if (type != 1)
    throw SceneError(path, "photometric type",
                     fmt::format("is {}{}; radmesh reads type C (1), the one for building luminaires", type,
                                 type == 2 ? " (type B)" : type == 3 ? " (type A)" : ", no type LM-63 defines"),
                     "export the luminaire's photometry as type C");
  if (units > 2) throw SceneError(path, "units type", fmt::format("is {}, not 1 (feet) or 2 (metres)", units), "use 1 or 2");
  const double unitM = units == 1 ? kFootM : 1.0;
  const std::vector<double> verticalDeg = numbers.list(vertical, "vertical angle");
  const std::vector<double> horizontalDeg = numbers.list(horizontal, "horizontal angle");
  checkAngles(verticalDeg, 0.0, 180.0, path, "vertical angle");
  checkAngles(horizontalDeg, 0.0, 360.0, path, "horizontal angle");
  std::vector<double> downPerPlane, upPerPlane;
  for (int h = 0; h < horizontal; ++h) {
    const std::string what = fmt::format("candela of horizontal angle {},", h + 1);
    const std::vector<double> candela = numbers.list(vertical, what);
    for (int v = 0; v < vertical; ++v)
      if (candela[v] < 0.0)
        throw SceneError(path, fmt::format("{} {}", what, v + 1), fmt::format("is {}: no light is negative", candela[v]),
                         "give candela values >= 0");
    double down = 0.0, up = 0.0;
    integrateVertical(verticalDeg, candela, down, up);
    downPerPlane.push_back(down);
    upPerPlane.push_back(up);
  }
  if (std::string extra; in >> extra)
    throw SceneError(path, "candela values",
                     fmt::format("are followed by more numbers ('{}'...) than the counts of angles ({} vertical, {} "
                                 "horizontal) take",
                                 extra, vertical, horizontal),
                     "correct the counts of angles, or remove what follows the candela values");
  // Around the vertical axis: trapezoids between the planes, the span given standing for the
  // whole circle by the file's symmetry (one plane: symmetric about the axis; 0-90: quadrants).
  const double span = horizontalDeg.back() - horizontalDeg.front();
  auto aroundAxis = [&](const std::vector<double>& perPlane) {
    if (horizontal == 1) return 2.0 * std::numbers::pi * perPlane[0];
    double sum = 0.0;
    for (int h = 0; h + 1 < horizontal; ++h)
      sum += 0.5 * (perPlane[h] + perPlane[h + 1]) * radians(horizontalDeg[h + 1] - horizontalDeg[h]);
    return sum * 360.0 / span;
  };
  if (horizontal > 1 && !(span > 0.0 && span <= 360.0))
    throw SceneError(path, "horizontal angles",
                     fmt::format("run from {} to {} degrees, not an increasing span of at most 360",
                                 horizontalDeg.front(), horizontalDeg.back()),
                     "give increasing horizontal angles");
  const double scale = multiplier * candelaMultiplier * ballast * ballastLamp;
  lum.downLumens = scale * aroundAxis(downPerPlane);
  lum.upLumens = scale * aroundAxis(upPerPlane);
  if (!(lum.downLumens + lum.upLumens > 0.0))
    throw SceneError(path, "candela values", "are all zero: the luminaire gives no light", "give its candela values");
  // LM-63-2002 marks a rounded opening by a negative size; its extent is the size's magnitude
  // (a negative width stays: a disc).
  lum.lengthM = std::abs(length) * unitM;
  lum.widthM = width * unitM;
  lum.heightM = std::abs(height) * unitM;
  // A point or line source still needs an area to leave from.
  if (lum.widthM == 0.0) lum.widthM = kPointOpeningM;
  if (lum.lengthM == 0.0 && lum.widthM > 0.0) lum.lengthM = kPointOpeningM;
  return lum;
}

}  // namespace radmesh
