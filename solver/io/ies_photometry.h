#pragma once
// IESNA LM-63 photometric files, as MGF's `ies` entity includes them: the luminaire's candela
// distribution integrated into the luminous flux it sends down and up, and its gross luminous
// opening, the surface that flux leaves from. Radiosity surfaces are diffuse, so the
// distribution's shape within each hemisphere is not kept, only its flux (docs/scene-formats.md).
#include <string>
#include <vector>

namespace radmesh {

struct IesLuminaire {
  double downLumens = 0.0;  // below the horizontal (type C vertical angles under 90 degrees)
  double upLumens = 0.0;    // above it
  // The gross luminous opening in metres: length along the 0-180 degree plane (x), width along
  // the 90-270 degree plane (y), height (z). A negative width is a disc of that diameter. A zero
  // width or length (a point or line source) is taken as 1 cm.
  double lengthM = 0.0;
  double widthM = 0.0;
  double heightM = 0.0;
  std::vector<std::string> notes;  // what was read but not applied (tilt data), for warnings
};

// Reads `path` (LM-63-1986, -1991, -1995 or -2002), all candela values times `multiplier` and the
// file's own candela multiplier and ballast factors. Throws SceneError naming the file and what in
// it cannot be read (a truncated file, a non-number, an unknown photometric type).
IesLuminaire readIes(const std::string& path, double multiplier);

}  // namespace radmesh
