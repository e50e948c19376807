#pragma once
// MGF's named contexts — colours (c), materials (m) and vertices (v) — and the entities that
// modify the current one of each. As in MGF, names are global across included files, a vertex
// keeps its untransformed position (transforms apply where it is used), and rd and ed take the
// colour that is current when they are given.
#include <map>
#include <string>
#include <utility>

#include "solver/io/mgf_color.h"
#include "solver/io/mgf_reader.h"

namespace radmesh {

struct MgfVertex {
  Vec3 position{0.0};
  Vec3 normal{0.0};  // zero: none given
};

struct MgfMaterial {
  double rd = 0.0;  // photometric diffuse reflectance
  Xyz rdColor = kMgfNeutral;
  double ed = 0.0;  // diffuse emittance, lm/m^2
  Xyz edColor = kMgfNeutral;
};

class MgfContexts {
 public:
  MgfContexts() = default;
  MgfContexts(const MgfContexts&) = delete;  // `current` points into the object itself
  MgfContexts& operator=(const MgfContexts&) = delete;

  // Handles c, cxy, cspec, cct, cmix, m, rd, ed, v, p and n, and checks rs, ts, td, ir and sides,
  // which radmesh cannot represent; returns false for any other entity. Throws MgfError for bad
  // arguments or undefined names.
  bool handle(const MgfEntity& entity);

  const MgfVertex& vertex(const std::string& name) const;  // throws MgfError when undefined
  const MgfMaterial& material() const { return *materials_.current; }
  const std::string& materialName() const { return materials_.currentName; }  // "" if unnamed
  // What the last handle() repaired (rd 1, an impossible chromaticity) or
  // passed over (a specular reflectance), as MGF's reference parser does: one message per kind, for
  // the caller to count and report.
  std::vector<std::string> takeNotes() { return std::exchange(notes_, {}); }

 private:
  bool ignore(const MgfEntity& entity);  // rs, ts, td, ir and sides: checked, noted, not kept
  std::vector<std::string> notes_;
  // The get/set pattern shared by c, m and v: "x" (the unnamed one, reset), "x id" (a defined
  // one), "x id =" (define id afresh), "x id = template" (define id as a copy).
  template <class T>
  struct Family {
    Family(const char* k, const T& initial) : keyword(k), unnamed(initial) {}
    const char* keyword;
    std::map<std::string, T> named;
    T unnamed;
    T* current = &unnamed;
    std::string currentName;
    void select(const MgfEntity& entity, const T& fresh);
    const T& find(const std::string& name) const;  // throws MgfError when undefined
    T& find(const std::string& name) { return const_cast<T&>(std::as_const(*this).find(name)); }
  };

  Family<Xyz> colors_{"c", kMgfNeutral};
  Family<MgfMaterial> materials_{"m", MgfMaterial{}};
  Family<MgfVertex> vertices_{"v", MgfVertex{}};
};

}  // namespace radmesh
