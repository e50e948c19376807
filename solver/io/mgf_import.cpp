// The MGF interpreter: walks the entities of a file and its includes, keeps the object and
// transform contexts, and turns geometry into scene polygons with the material current at the
// time. Colours, named contexts, transforms and primitives live in their own mgf_* files.
#include "solver/io/mgf_import.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <numbers>

#include "solver/io/file_signature.h"
#include "solver/io/ies_photometry.h"
#include "solver/io/mgf_color.h"
#include "solver/io/mgf_context.h"
#include "solver/io/mgf_error.h"
#include "solver/io/mgf_face.h"
#include "solver/io/mgf_primitives.h"
#include "solver/io/mgf_reader.h"
#include "solver/io/mgf_transform.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

namespace fs = std::filesystem;

// Beyond these the input is refused rather than allowed to exhaust memory.
constexpr size_t kMaxPolygons = 2'000'000;
constexpr size_t kMaxIncludeDepth = 64;
// Includes read anew each time: a file that includes another twice, at each of 22 levels, reads
// four million files.
constexpr size_t kMaxIncludedReads = 100'000;

// A warning given once however often it applies: where it first did, and how often.
struct Note {
  std::string firstAt;
  int count = 0;
};

struct OpenFile {
  fs::path path;
  fs::path canonical;     // to recognise include cycles
  std::string label;      // "" for the top file, else its file name, for messages
  size_t transformDepth;  // transforms_ size when it began: its xf must close inside it
};

fs::path canonicalOf(const fs::path& p) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(p, ec);
  return ec ? p.lexically_normal() : c;
}

class MgfInterpreter {
 public:
  explicit MgfInterpreter(const std::string& path) { scene_.source = path; }
  Scene run(std::vector<std::string>* warnings);

 private:
  void load(const fs::path& path, const std::string& label);
  void entity(const MgfEntity& e);
  void include(const MgfEntity& e);
  void luminaire(const MgfEntity& e);
  fs::path includedPath(const std::string& name, const char* what) const;
  void transform(const MgfEntity& e);
  void pushTransform(const std::vector<std::string>& args, int line);
  void popTransform();
  void object(const MgfEntity& e);
  bool geometry(const MgfEntity& e);
  void note(const MgfEntity& e, const std::string& message);
  void emit(const MgfPolygons& polygons, const MgfEntity& e);
  void emit(const MgfPolygons& polygons, const MgfEntity& e, int material);
  int currentMaterial(const MgfEntity& e);
  Vec3 position(const std::string& vertex) const { return contexts_.vertex(vertex).position; }
  std::string where(int line) const {
    const std::string& label = files_.back().label;
    return (label.empty() ? "" : label + " ") + "line " + std::to_string(line);
  }

  Scene scene_;
  MgfContexts contexts_;
  // One entry per open xf (or include with a transform): every instance transform in force, outer
  // and inner arrays combined, and the line that opened it.
  std::vector<std::vector<MgfAffine>> transforms_{{MgfAffine{}}};
  std::vector<int> transformLines_{0};
  std::vector<std::string> objects_;
  std::vector<OpenFile> files_;
  size_t includedReads_ = 0;
  std::map<std::string, Note> notes_;  // by message
  std::map<std::string, std::vector<int>> materialsByName_;
  std::vector<std::string> warnings_;
};

Scene MgfInterpreter::run(std::vector<std::string>* warnings) {
  load(scene_.source, "");
  for (const auto& [message, n] : notes_)
    warnings_.push_back(scene_.source + ": " + n.firstAt + ": " + message +
                        (n.count > 1 ? " (" + std::to_string(n.count) + " times)" : ""));
  if (!objects_.empty())
    warnings_.push_back(scene_.source + ": object '" + objects_.back() +
                        "' is still open at the end (a missing 'o' line?)");
  if (warnings) warnings->insert(warnings->end(), warnings_.begin(), warnings_.end());
  return std::move(scene_);
}

void MgfInterpreter::load(const fs::path& path, const std::string& label) {
  const std::vector<MgfEntity> entities = readMgfEntities(path.string());
  files_.push_back({path, canonicalOf(path), label, transforms_.size()});
  for (const MgfEntity& e : entities) {
    try {
      entity(e);
    } catch (const MgfError& error) {
      throw SceneError(path.string(), "line " + std::to_string(e.line) + ": " + e.words[0],
                       error.what(), error.fix());
    }
  }
  if (transforms_.size() > files_.back().transformDepth)
    throw SceneError(path.string(), "line " + std::to_string(transformLines_.back()) + ": xf",
                     "the file ends with this transform still open (truncated file?)",
                     "close it with a line holding only 'xf', or restore the end of the file");
  files_.pop_back();
}

void MgfInterpreter::entity(const MgfEntity& e) {
  const std::string& k = e.words[0];
  if (contexts_.handle(e)) {
    for (const std::string& message : contexts_.takeNotes()) note(e, message);
    return;
  }
  if (geometry(e)) return;
  if (k == "xf") return transform(e);
  if (k == "o") return object(e);
  if (k == "i") return include(e);
  if (k == "ies") return luminaire(e);
  // As MGF's reference parser does: counted and passed over, so files of newer or private
  // dialects still open.
  note(e, "unknown entity '" + k + "' skipped (radmesh reads the MGF 2.0 entities # o xf i ies c cxy "
          "cspec cct cmix m sides rd td ed rs ts ir v p n f sph cyl cone prism ring torus)");
}

fs::path MgfInterpreter::includedPath(const std::string& name, const char* what) const {
  fs::path target = name;
  if (target.is_relative()) target = files_.back().path.parent_path() / target;
  const FileKind kind = fileKind(target);
  if (kind == FileKind::Folder || kind == FileKind::Special)
    throw MgfError(std::string(what) + " '" + name + "' is not a file (" + target.string() + " is " +
                       fileKindName(kind) + ")",
                   "name the file to read");
  if (kind == FileKind::Missing)
    throw MgfError(std::string(what) + " '" + name + "' not found (looked for " + target.string() + ")",
                   "check the name; include paths are relative to the including file's folder");
  return target;
}

// An IES luminaire (the ies entity): its gross luminous opening, centred at the origin with the
// 0-180 degree plane along x and up along z, emitting its downward flux from its underside and its
// upward flux from its top, as diffuse emitters of the same total flux.
void MgfInterpreter::luminaire(const MgfEntity& e) {
  requireMgfArguments(e, 1, SIZE_MAX, "ies pathname [-m multiplier] [xform]");
  const fs::path target = includedPath(e.words[1], "IES file");
  size_t first = 2;
  double multiplier = 1.0;
  if (e.words.size() > 2 && e.words[2] == "-m") {
    if (e.words.size() < 4) throw MgfError("-m is missing its multiplier", "write ies file -m 2.5");
    multiplier = parseMgfNumber(e.words[3], "multiplier");
    if (multiplier < 0.0) throw MgfError("the multiplier is negative", "give -m a value >= 0");
    first = 4;
  }
  const IesLuminaire lum = readIes(target.string(), multiplier);
  for (const std::string& n : lum.notes) note(e, "ies " + target.filename().string() + ": " + n);
  // Clockwise seen from above, so that the underside faces down.
  std::vector<Vec3> opening;
  const double z = -lum.heightM / 2.0;
  if (lum.widthM < 0.0) {  // a disc
    for (int k = 0; k < kMgfSegmentsAround; ++k) {
      const double angle = -2.0 * std::numbers::pi * k / kMgfSegmentsAround;
      opening.push_back({-lum.widthM / 2.0 * std::cos(angle), -lum.widthM / 2.0 * std::sin(angle), z});
    }
  } else {
    const double x = lum.lengthM / 2.0, y = lum.widthM / 2.0;
    opening = {{-x, -y, z}, {-x, y, z}, {x, y, z}, {x, -y, z}};
  }
  const double area = polygonArea(opening);
  const bool transformed = e.words.size() > first;
  if (transformed) pushTransform(std::vector<std::string>(e.words.begin() + first, e.words.end()), e.line);
  for (const bool up : {false, true}) {
    const double lumens = up ? lum.upLumens : lum.downLumens;
    if (!(lumens > 0.0)) continue;
    std::vector<Vec3> face = opening;
    if (up) {
      std::reverse(face.begin(), face.end());
      for (Vec3& v : face) v.z = lum.heightM / 2.0;
    }
    const std::string name = fmt::format("ies {} ({})", target.filename().string(), up ? "up" : "down");
    const Rgb exitance = mgfEmittance(lumens / area, kMgfNeutral, nullptr);
    // Refused here, where the fix is known: the scene's check would ask for an emittance this file never gave.
    const double most = std::max({exitance.r, exitance.g, exitance.b});
    if (!(most > 0.0 && trustedEmission(most)))
      throw MgfError(fmt::format("{} sends {:g} lm {} from its {:g} m^2 opening: {:g} W/m^2, outside the {:g} to {:g} "
                                 "W/m^2 radmesh trusts (no real luminaire comes near)",
                                 target.filename().string(), lumens, up ? "up" : "down", area, most, kMinEmitted,
                                 kMaxEmitted),
                     fmt::format("check -m (here {:g}) and the candela multiplier and values in {}", multiplier,
                                 target.string()));
    scene_.materials.push_back({name, Rgb(0.0), exitance});
    emit({face}, e, static_cast<int>(scene_.materials.size()) - 1);
  }
  if (transformed) popTransform();
}

void MgfInterpreter::include(const MgfEntity& e) {
  requireMgfArguments(e, 1, SIZE_MAX, "i pathname [xform]");
  const fs::path target = includedPath(e.words[1], "include file");
  const fs::path canonical = canonicalOf(target);
  for (size_t i = 0; i < files_.size(); ++i) {
    if (files_[i].canonical != canonical) continue;
    std::string chain;
    for (size_t j = i; j < files_.size(); ++j) chain += files_[j].path.filename().string() + " -> ";
    throw MgfError("include cycle: " + chain + target.filename().string(),
                   "remove the include that leads back to a file already being read");
  }
  if (files_.size() >= kMaxIncludeDepth)
    throw MgfError("includes nest deeper than " + std::to_string(kMaxIncludeDepth) + " files",
                   "flatten the include hierarchy");
  if (++includedReads_ > kMaxIncludedReads)
    throw MgfError("more than " + std::to_string(kMaxIncludedReads) + " files included in all",
                   "include each file fewer times (an include repeated at every level multiplies)");
  const bool transformed = e.words.size() > 2;
  if (transformed) pushTransform(std::vector<std::string>(e.words.begin() + 2, e.words.end()), e.line);
  load(target, target.filename().string());
  if (transformed) popTransform();
}

void MgfInterpreter::transform(const MgfEntity& e) {
  if (e.words.size() > 1)
    return pushTransform(std::vector<std::string>(e.words.begin() + 1, e.words.end()), e.line);
  if (transforms_.size() <= files_.back().transformDepth)
    throw MgfError("xf ends a transform, but none is open in this file",
                   "remove this line or add the 'xf arguments...' line it should close");
  popTransform();
}

void MgfInterpreter::pushTransform(const std::vector<std::string>& args, int line) {
  const std::vector<MgfAffine> inner = mgfTransformInstances(args);
  const std::vector<MgfAffine>& outer = transforms_.back();
  if (inner.size() * outer.size() > kMaxMgfInstances)
    throw MgfError("nested arrays make more than " + std::to_string(kMaxMgfInstances) + " instances",
                   "use smaller -a counts");
  // MGF prepends a context's arguments to those of the contexts around it: inner acts first.
  std::vector<MgfAffine> combined;
  for (const MgfAffine& o : outer)
    for (const MgfAffine& i : inner) combined.push_back(i.then(o));
  transforms_.push_back(std::move(combined));
  transformLines_.push_back(line);
}

void MgfInterpreter::popTransform() {
  transforms_.pop_back();
  transformLines_.pop_back();
}

void MgfInterpreter::object(const MgfEntity& e) {
  requireMgfArguments(e, 0, 1, "o [name]");
  if (e.words.size() == 2) return objects_.push_back(e.words[1]);
  if (objects_.empty())
    throw MgfError("o ends an object, but none is open",
                   "remove this line or add the 'o name' line it should close");
  objects_.pop_back();
}

bool MgfInterpreter::geometry(const MgfEntity& e) {
  const std::string& k = e.words[0];
  const auto number = [&](size_t i, const char* what) { return parseMgfNumber(e.words[i], what); };
  if (k == "f") {
    requireMgfArguments(e, 3, SIZE_MAX, "f v1 v2 v3 ...");
    // A face that cannot be built is skipped, as MGF's reference parser does, not the whole file.
    bool split = false;
    std::vector<std::vector<Vec3>> polygons;
    try {
      std::vector<Vec3> face;
      for (size_t i = 1; i < e.words.size(); ++i) face.push_back(position(e.words[i]));
      polygons = planarFace(face, &split);
    } catch (const MgfError& error) {
      note(e, std::string("f skipped: ") + error.what() + " (fix: " + error.fix() + ")");
      return true;
    }
    emit(polygons, e);
    if (split) note(e, "f split into triangles: its vertices are not in one plane");
  } else if (k == "sph") {
    requireMgfArguments(e, 2, 2, "sph vc radius");
    const Vec3 centre = position(e.words[1]);
    emit(tessellateSphere(centre, number(2, "radius")), e);
  } else if (k == "cyl" || k == "cone") {
    const bool cone = k == "cone";
    requireMgfArguments(e, cone ? 4 : 3, cone ? 4 : 3, cone ? "cone v1 rad1 v2 rad2" : "cyl v1 radius v2");
    const Vec3 end1 = position(e.words[1]);
    const double radius1 = number(2, "radius");
    const Vec3 end2 = position(e.words[3]);
    const double radius2 = cone ? number(4, "radius") : radius1;
    emit(tessellateCone(end1, radius1, end2, radius2), e);
  } else if (k == "ring" || k == "torus") {
    requireMgfArguments(e, 3, 3, k + " vc rmin rmax");
    const MgfVertex& centre = contexts_.vertex(e.words[1]);
    const double rMin = number(2, "rmin");
    const double rMax = number(3, "rmax");
    emit(k == "ring" ? tessellateRing(centre.position, centre.normal, rMin, rMax)
                     : tessellateTorus(centre.position, centre.normal, rMin, rMax),
         e);
  } else if (k == "prism") {
    requireMgfArguments(e, 4, SIZE_MAX, "prism v1 v2 v3 ... length");
    std::vector<Vec3> base;
    for (size_t i = 1; i + 1 < e.words.size(); ++i) base.push_back(position(e.words[i]));
    emit(tessellatePrism(base, number(e.words.size() - 1, "length")), e);
  } else {
    return false;
  }
  return true;
}

void MgfInterpreter::note(const MgfEntity& e, const std::string& message) {
  Note& n = notes_[message];
  if (n.count++ == 0) n.firstAt = where(e.line);
}

void MgfInterpreter::emit(const MgfPolygons& polygons, const MgfEntity& e) {
  emit(polygons, e, currentMaterial(e));
}

void MgfInterpreter::emit(const MgfPolygons& polygons, const MgfEntity& e, int material) {
  if (scene_.polygons.size() + transforms_.back().size() * polygons.size() > kMaxPolygons)
    throw MgfError("the scene would have more than " + std::to_string(kMaxPolygons) + " polygons",
                   "use fewer or smaller arrays");
  std::string origin = where(e.line) + ": " + e.words[0];
  if (!objects_.empty()) {
    origin += " (object '" + objects_.front();
    for (size_t i = 1; i < objects_.size(); ++i) origin += "/" + objects_[i];
    origin += "')";
  }
  for (const MgfAffine& t : transforms_.back()) {
    for (const std::vector<Vec3>& local : polygons) {
      Polygon p{{}, material, origin};
      for (const Vec3& v : local) {
        p.vertices.push_back(t.point(v));
        checkMgfPoint(p.vertices.back(), "a vertex placed at", "check the radii and xf scales that place it");
      }
      if (t.mirrors()) std::reverse(p.vertices.begin(), p.vertices.end());
      dropRepeatedVertices(p.vertices);
      if (p.vertices.size() >= 3) scene_.polygons.push_back(std::move(p));  // else a pole or apex
    }
  }
}

int MgfInterpreter::currentMaterial(const MgfEntity& e) {
  const MgfMaterial& m = contexts_.material();
  const std::string name = contexts_.materialName().empty() ? "(unnamed)" : contexts_.materialName();
  ColorRepair rhoRepair = ColorRepair::kNone;
  ColorRepair emittanceRepair = ColorRepair::kNone;
  const Rgb rho = mgfReflectance(m.rd, m.rdColor, &rhoRepair);
  const Rgb emittance = mgfEmittance(m.ed, m.edColor, &emittanceRepair);
  // A material redefined after use becomes a second scene material ("name #2").
  std::vector<int>& sameName = materialsByName_[name];
  for (int i : sameName)
    if (scene_.materials[i].rho == rho && scene_.materials[i].emittance == emittance) return i;
  const std::string unique = sameName.empty() ? name : name + " #" + std::to_string(sameName.size() + 1);
  const std::string material = scene_.source + ": " + where(e.line) + ": material '" + unique + "': its colour ";
  if (rhoRepair == ColorRepair::kOutsideGamut || emittanceRepair == ColorRepair::kOutsideGamut)
    warnings_.push_back(material + "lies outside the Rec. 709 gamut; desaturated toward grey, keeping its luminance");
  else if (rhoRepair == ColorRepair::kTooSaturated)
    warnings_.push_back(material + fmt::format("is too saturated for rd {:g}: a channel would pass {:g}; desaturated "
                                               "toward grey, keeping its luminance",
                                               m.rd, kHighestReflectance));
  sameName.push_back(static_cast<int>(scene_.materials.size()));
  scene_.materials.push_back({unique, rho, emittance});
  return sameName.back();
}

}  // namespace

Scene importMgf(const std::string& path, std::vector<std::string>* warnings) {
  return MgfInterpreter(path).run(warnings);
}

}  // namespace radmesh
