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

// Integral of I(theta) sin(theta) over each segment, I linear in theta between the angles given,
// added to `down` below the horizontal (theta < 90 degrees from nadir) and to `up` above it.
void integrateVertical(const std::vector<double>& anglesDeg, const std::vector<double>& candela, double& down,
                       double& up) {
  for (size_t k = 0; k + 1 < anglesDeg.size(); ++k) {
    const double a = radians(anglesDeg[k]), b = radians(anglesDeg[k + 1]);
    if (!(b > a)) continue;
    const double slope = (candela[k + 1] - candela[k]) / (b - a);
    const double flux = candela[k] * (std::cos(a) - std::cos(b)) +
                        slope * (std::sin(b) - std::sin(a) - (b - a) * std::cos(b));
    (anglesDeg[k] + anglesDeg[k + 1] < 180.0 ? down : up) += flux;
  }
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
  const int vertical = numbers.count("number of vertical angles", 2);
  const int horizontal = numbers.count("number of horizontal angles", 1);
  const int type = numbers.count("photometric type", 1);
  const int units = numbers.count("units type", 1);
  const double width = numbers.next("width"), length = numbers.next("length"), height = numbers.next("height");
  const double ballast = numbers.next("ballast factor");
  const double ballastLamp = numbers.next("ballast-lamp photometric factor");
  numbers.next("input watts");
  if (type != 1)
    throw SceneError(path, "photometric type",
                     fmt::format("is {} (type {}); radmesh reads type C (1), the one for building luminaires", type,
                                 type == 2 ? "B" : "A"),
                     "export the luminaire's photometry as type C");
  if (units > 2) throw SceneError(path, "units type", fmt::format("is {}, not 1 (feet) or 2 (metres)", units), "use 1 or 2");
  const double unitM = units == 1 ? kFootM : 1.0;
  const std::vector<double> verticalDeg = numbers.list(vertical, "vertical angle");
  const std::vector<double> horizontalDeg = numbers.list(horizontal, "horizontal angle");
  std::vector<double> downPerPlane, upPerPlane;
  for (int h = 0; h < horizontal; ++h) {
    double down = 0.0, up = 0.0;
    integrateVertical(verticalDeg, numbers.list(vertical, fmt::format("candela of horizontal angle {},", h + 1)),
                      down, up);
    downPerPlane.push_back(down);
    upPerPlane.push_back(up);
  }
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
  if (!(lum.downLumens >= 0.0) || !(lum.upLumens >= 0.0))
    throw SceneError(path, "candela values", "give a negative luminous flux", "give candela values >= 0");
  lum.lengthM = length * unitM;
  lum.widthM = width * unitM;
  lum.heightM = height * unitM;
  // A point or line source still needs an area to leave from.
  if (lum.widthM == 0.0) lum.widthM = kPointOpeningM;
  if (lum.lengthM == 0.0 && lum.widthM > 0.0) lum.lengthM = kPointOpeningM;
  return lum;
}

}  // namespace radmesh
