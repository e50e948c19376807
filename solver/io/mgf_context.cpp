#include "solver/io/mgf_context.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "solver/io/mgf_error.h"

namespace radmesh {

namespace {

std::vector<double> numbers(const MgfEntity& e, size_t first, size_t count, const std::string& what) {
  std::vector<double> values;
  for (size_t k = first; k < first + count; ++k) values.push_back(parseMgfNumber(e.words[k], what));
  return values;
}

Vec3 vector3(const MgfEntity& e, const std::string& what) {
  const std::vector<double> v = numbers(e, 1, 3, what);
  return {v[0], v[1], v[2]};
}

// Argument `i` of `e`, a fraction of light (rd, td, rs, ts): MGF's reference parser refuses one
// outside [0, 1] as illegal (MG_EILL), and so does radmesh.
double checkFraction(const MgfEntity& e, size_t i, const std::string& what) {
  const std::string& k = e.words[0];
  const double value = parseMgfNumber(e.words[i], what);
  if (value < 0.0 || value > 1.0)
    throw MgfError(fmt::format("{} {} is {}", what, e.words[i],
                               value < 0.0 ? "negative" : "above 1 (more light than falls on the surface)"),
                   fmt::format("write {} as a fraction of the light, from 0 up to 1 (50% is 0.5)", k));
  return value;
}

// Material entities radmesh reads and checks but cannot represent, and why.
struct IgnoredEntity {
  const char* keyword;
  size_t arguments;
  const char* usage;
  const char* fraction;  // what the first argument is, when it is a fraction of light
  const char* why;
};
constexpr IgnoredEntity kIgnoredEntities[] = {
    {"rs", 2, "rs rho_s alpha_r", "specular reflectance", "specular reflectance, radmesh surfaces are ideal diffusers"},
    {"ts", 2, "ts tau_s alpha_t", "specular transmittance", "specular transmittance, radmesh surfaces are opaque"},
    {"td", 1, "td tau_d", "diffuse transmittance", "diffuse transmittance, radmesh surfaces are opaque"},
    {"ir", 2, "ir n_real n_imag", nullptr, "index of refraction, radmesh surfaces are opaque"},
    {"sides", 1, "sides {1|2}", nullptr,
     "radmesh surfaces are one-sided, as RenderPark reads MGF by default: they emit and receive on their "
     "right-hand-rule front"},
};

}  // namespace

template <class T>
void MgfContexts::Family<T>::select(const MgfEntity& e, const T& fresh) {
  const std::string k = keyword;
  requireMgfArguments(e, 0, 3, k + " [name [= [template]]]");
  if (e.words.size() == 1) {
    unnamed = fresh;
    current = &unnamed;
    currentName.clear();
    return;
  }
  const std::string& name = e.words[1];
  if (e.words.size() == 2) {
    current = &find(name);
    currentName = name;
    return;
  }
  if (e.words[2] != "=")
    throw MgfError("expected '=' after the name, found '" + e.words[2] + "'",
                   "write " + k + " " + name + " = [template]");
  const T value = e.words.size() == 4 ? find(e.words[3]) : fresh;
  current = &(named[name] = value);
  currentName = name;
}

template <class T>
const T& MgfContexts::Family<T>::find(const std::string& name) const {
  const auto it = named.find(name);
  if (it == named.end())
    throw MgfError(std::string(keyword) + " '" + name + "' is not defined",
                   std::string("define it first with ") + keyword + " " + name + " = ...");
  return it->second;
}

const MgfVertex& MgfContexts::vertex(const std::string& name) const { return vertices_.find(name); }

bool MgfContexts::handle(const MgfEntity& e) {
  const std::string& k = e.words[0];
  Xyz& color = *colors_.current;
  MgfMaterial& material = *materials_.current;
  MgfVertex& vertex = *vertices_.current;
  if (k == "c") {
    colors_.select(e, kMgfNeutral);
  } else if (k == "cxy") {
    requireMgfArguments(e, 2, 2, "cxy x y");
    double x = parseMgfNumber(e.words[1], "x");
    double y = parseMgfNumber(e.words[2], "y");
    // MGF's reference parser refuses x < 0, y < 0 or x + y > 1 (MG_EILL), as xyzFromChromaticity
    // does. y = 0 it accepts, though no colour of luminance 1 lies there: raised just above it.
    if (y == 0.0 && x >= 0.0 && x <= 1.0) {
      y = 1e-6;
      x = std::min(x, 1.0 - y);
      notes_.push_back(fmt::format("cxy y 0 (light of no luminance, which rd and ed cannot scale) raised to {:g}", y));
    }
    color = xyzFromChromaticity(x, y);
  } else if (k == "cspec") {
    requireMgfArguments(e, 4, SIZE_MAX, "cspec l_min l_max v1 v2 ...");
    color = xyzFromSpectrum(parseMgfNumber(e.words[1], "l_min"), parseMgfNumber(e.words[2], "l_max"),
                            numbers(e, 3, e.words.size() - 3, "spectral value"));
  } else if (k == "cct") {
    requireMgfArguments(e, 1, 1, "cct temperature");
    color = xyzFromTemperature(parseMgfNumber(e.words[1], "temperature"));
  } else if (k == "cmix") {
    if (e.words.size() < 3 || e.words.size() % 2 == 0)
      throw MgfError("cmix needs pairs of weight and colour name", "write it as: cmix w1 c1 w2 c2 ...");
    std::vector<double> weights;
    std::vector<Xyz> mixed;
    for (size_t i = 1; i < e.words.size(); i += 2) {
      weights.push_back(parseMgfNumber(e.words[i], "weight"));
      mixed.push_back(colors_.find(e.words[i + 1]));
    }
    color = mixColors(weights, mixed);
  } else if (k == "m") {
    materials_.select(e, MgfMaterial{});
  } else if (k == "rd") {
    requireMgfArguments(e, 1, 1, "rd rho_d");
    const double rd = checkFraction(e, 1, "diffuse reflectance");
    // MGF allows rd 1 and files in the wild write it for white, but rho = 1 would never let light
    // die out: lowered, as in every reader; so is anything above kHighestReflectance, as glTF's is.
    if (rd == 1.0)
      notes_.push_back(fmt::format("rd 1 lowered to {} (a reflectance of 1 never lets light die out)",
                                   kHighestReflectance));
    else if (rd > kHighestReflectance)
      notes_.push_back(fmt::format("rd {} lowered to {} (the highest reflectance radmesh solves: the nearer 1, the "
                                   "longer light takes to die out)",
                                   e.words[1], kHighestReflectance));
    material.rd = std::min(rd, kHighestReflectance);
    material.rdColor = color;
  } else if (k == "ed") {
    requireMgfArguments(e, 1, 1, "ed epsilon_d");
    const double ed = parseMgfNumber(e.words[1], "epsilon_d");
    if (ed < 0.0)
      throw MgfError("emittance " + e.words[1] + " is negative", "give ed in lm/m^2, >= 0");
    material.ed = ed;
    material.edColor = color;
  } else if (k == "v") {
    vertices_.select(e, MgfVertex{});
  } else if (k == "p") {
    requireMgfArguments(e, 3, 3, "p x y z");
    vertex.position = vector3(e, "coordinate");
    checkMgfPoint(vertex.position, "the point", "check the coordinates");
  } else if (k == "n") {
    requireMgfArguments(e, 3, 3, "n dx dy dz");
    vertex.normal = vector3(e, "normal component");
  } else {
    return ignore(e);
  }
  return true;
}

bool MgfContexts::ignore(const MgfEntity& e) {
  const std::string& k = e.words[0];
  for (const IgnoredEntity& ignored : kIgnoredEntities) {
    if (k != ignored.keyword) continue;
    requireMgfArguments(e, ignored.arguments, ignored.arguments, ignored.usage);
    if (k == "sides" && e.words[1] != "1" && e.words[1] != "2")
      throw MgfError("sides must be 1 or 2", "write sides 1 or sides 2");
    // The reference parser refuses a real index of refraction up to 1e-6 (its FTINY) as illegal;
    // the imaginary part, absorption, may be any number.
    if (k == "ir" && !(parseMgfNumber(e.words[1], "n_real") > 1e-6))
      throw MgfError(fmt::format("real index of refraction {} is not above 1e-6", e.words[1]),
                     "give ir the refractive index, then the absorption, e.g. ir 1.5 0 for glass");
    // Their fractions of light lie in [0, 1] and roughnesses are >= 0, or MGF's reference parser
    // refuses the file (MG_EILL): so does radmesh, though it keeps none of them.
    if (ignored.fraction) checkFraction(e, 1, ignored.fraction);
    for (size_t i = ignored.fraction ? 2 : 1; i < e.words.size(); ++i)
      if (const double value = parseMgfNumber(e.words[i], k + " value"); value < 0.0 && k != "ir")
        throw MgfError(fmt::format("{} value {} is negative", k, e.words[i]), fmt::format("give {} values >= 0", k));
    // sides 1 asks for what radmesh does: only sides 2 is not honoured.
    if (k != "sides") notes_.push_back(k + " ignored: " + ignored.why);
    else if (e.words[1] == "2") notes_.push_back("sides 2 ignored: " + std::string(ignored.why));
    return true;
  }
  return false;
}

}  // namespace radmesh
