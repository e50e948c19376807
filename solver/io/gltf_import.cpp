#include "solver/io/gltf_import.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "solver/geometry/coplanar_merge.h"
#include "solver/io/gltf_accessor.h"
#include "solver/io/gltf_lights.h"
#include "solver/io/gltf_load.h"
#include "solver/io/gltf_material.h"
#include "solver/scene/note_tally.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

bool finiteMatrix(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

std::string nodeLabel(const tinygltf::Model& model, int index) {
  const std::string& name = model.nodes[index].name;
  return "node " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

// A triangle list (three indices a triangle, counter-clockwise) from a list, strip or fan, as
// glTF 2.0 defines them (section 3.7.2.1): strip triangle i is (i, i+1+i%2, i+2-i%2), fan
// triangle i is (i+1, i+2, 0).
std::vector<uint32_t> triangleList(int mode, const std::vector<uint32_t>& v, const std::string& file,
                                   const std::string& element) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (v.size() % 3 != 0)
      throw SceneError(file, element, "has " + std::to_string(v.size()) + " vertices, not a multiple of 3 for triangles",
                       "give each triangle exactly 3 indices");
    return v;
  }
  if (v.size() < 3)
    throw SceneError(file, element, "has " + std::to_string(v.size()) + " vertices, fewer than one triangle needs",
                     "give a strip or fan at least 3 vertices");
  std::vector<uint32_t> out;
  for (size_t i = 0; i + 2 < v.size(); ++i) {
    const size_t odd = mode == TINYGLTF_MODE_TRIANGLE_STRIP ? i % 2 : 0;
    const std::array<uint32_t, 3> t = mode == TINYGLTF_MODE_TRIANGLE_STRIP
                                          ? std::array<uint32_t, 3>{v[i], v[i + 1 + odd], v[i + 2 - odd]}
                                          : std::array<uint32_t, 3>{v[i + 1], v[i + 2], v[0]};
    out.insert(out.end(), t.begin(), t.end());
  }
  return out;
}

// Collects the triangles of every mesh instance under the chosen scene roots, in world space.
class TriangleCollector {
 public:
  TriangleCollector(const tinygltf::Model& model, const std::string& file, std::vector<std::string>* warnings)
      : model_(model), file_(file), warnings_(warnings), onPath_(model.nodes.size(), false) {}

  // glTF's transform hierarchy (glTF 2.0 spec, 3.5.2): world = parent x local. Walked with a stack
  // of its own, depth first in the file's order: recursion overflowed the call stack on a chain of
  // 30000 nested nodes.
  void visit(int root, const std::string& referrer) {
    struct Step {
      int node;
      glm::dmat4 parent;
      std::string referrer;
      bool leaving;  // its subtree is done: it leaves the current path
    };
    std::vector<Step> steps{{root, glm::dmat4(1.0), referrer, false}};
    while (!steps.empty()) {
      const Step step = std::move(steps.back());
      steps.pop_back();
      const int node = step.node;
      if (step.leaving) {
        onPath_[node] = false;
        continue;
      }
      if (node < 0 || static_cast<size_t>(node) >= model_.nodes.size())
        throw SceneError(file_, step.referrer, "refers to node " + std::to_string(node) + ", which does not exist",
                         "refer to existing nodes only");
      const std::string element = nodeLabel(model_, node);
      if (onPath_[node])
        throw SceneError(file_, element, "is its own ancestor (the node hierarchy has a cycle)",
                         "make the node hierarchy a tree");
      const glm::dmat4 world = step.parent * localTransform(model_.nodes[node], element);
      if (!finiteMatrix(world))
        throw SceneError(file_, element, "has a NaN or infinite transform", "give the node a finite transform");
      onPath_[node] = true;
      if (model_.nodes[node].mesh >= 0) addMesh(model_.nodes[node].mesh, world, element);
      if (const int light = gltfNodeLight(model_.nodes[node]); light >= 0)
        lights_.push_back(gltfLight(model_, light, world, file_, element, &rangeIgnored_));
      steps.push_back({node, {}, {}, true});
      const std::vector<int>& children = model_.nodes[node].children;
      for (auto child = children.rbegin(); child != children.rend(); ++child)  // reversed: popped in order
        steps.push_back({*child, world, "children of " + element, false});
    }
  }

  std::vector<Polygon>& triangles() { return triangles_; }
  const std::vector<Light>& lights() const { return lights_; }
  int rangeIgnored() const { return rangeIgnored_; }
  const NoteTally& repairs() const { return repairs_; }
  // Per triangle, its vertices' COLOR_0; empty once a triangle primitive had none.
  std::vector<std::array<Rgb, 3>> colours() const { return uncoloured_ ? std::vector<std::array<Rgb, 3>>{} : colours_; }
  int defaultMaterialUsers() const { return defaultMaterialUsers_; }

 private:
  // The arrays' lengths were checked in the JSON (checkGltfTypes); an empty one is absent.
  glm::dmat4 localTransform(const tinygltf::Node& n, const std::string& element) {
    if (!n.matrix.empty()) {
      // glTF 2.0 (5.25): a node's matrix is a translation, rotation and scale; its last row was
      // dropped unread, moving the geometry silently.
      if (n.matrix[3] != 0.0 || n.matrix[7] != 0.0 || n.matrix[11] != 0.0 || n.matrix[15] != 1.0)
        throw SceneError(file_, element,
                         fmt::format("its matrix's last row is ({}, {}, {}, {}), not (0, 0, 0, 1): a projective "
                                     "matrix, where glTF allows only translation, rotation and scale",
                                     n.matrix[3], n.matrix[7], n.matrix[11], n.matrix[15]),
                         "export the node's transform as translation, rotation and scale");
      return glm::make_mat4(n.matrix.data());  // both column-major
    }
    glm::dmat4 m(1.0);
    if (!n.translation.empty()) m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    if (!n.rotation.empty()) m *= glm::mat4_cast(unitRotation(n.rotation, element));
    if (!n.scale.empty()) m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
  }

  // glTF stores the quaternion as (x, y, z, w); glm's constructor takes w first. glTF requires a
  // unit quaternion, and one that is not would scale and shear too (mat4_cast assumes unit
  // length): it is normalised, with a warning past the Khronos validator's tolerance (0.00769,
  // above the rounding of 8-bit quantised rotations).
  glm::dquat unitRotation(const std::vector<double>& r, const std::string& element) {
    const glm::dquat q(r[3], r[0], r[1], r[2]);
    bool finite = true;
    double largest = 0.0;  // dividing by it first keeps tiny and huge quaternions from under/overflowing
    for (double v : r) {
      finite = finite && std::isfinite(v);
      largest = std::max(largest, std::abs(v));
    }
    if (!finite || largest == 0.0)
      throw SceneError(file_, element,
                       fmt::format("rotation ({}, {}, {}, {}) is zero or not finite: no rotation", r[0], r[1], r[2], r[3]),
                       "give rotation as a unit quaternion (x, y, z, w), [0, 0, 0, 1] for none");
    const double length = glm::length(q / largest);
    if (std::abs(length * largest - 1.0) > 0.00769)
      repairs_.add("rotation", fmt::format("{}: {}: rotation ({}, {}, {}, {}) has length {:.6g}, not 1: normalised "
                                           "(glTF 2.0 requires a unit quaternion)",
                                           file_, element, r[0], r[1], r[2], r[3], length * largest));
    return q / largest / length;
  }

  void addMesh(int mesh, const glm::dmat4& world, const std::string& element) {
    if (static_cast<size_t>(mesh) >= model_.meshes.size())
      throw SceneError(file_, element, "refers to mesh " + std::to_string(mesh) + ", which does not exist",
                       "refer to an existing mesh");
    const std::string& name = model_.meshes[mesh].name;
    const std::string label = name.empty() ? "mesh " + std::to_string(mesh) : "mesh '" + name + "'";
    for (size_t p = 0; p < model_.meshes[mesh].primitives.size(); ++p)
      addPrimitive(model_.meshes[mesh].primitives[p], world, label + " primitive " + std::to_string(p), element);
  }

  void addPrimitive(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& element,
                    const std::string& node) {
    if (prim.mode == TINYGLTF_MODE_POINTS || prim.mode == TINYGLTF_MODE_LINE ||
        prim.mode == TINYGLTF_MODE_LINE_LOOP || prim.mode == TINYGLTF_MODE_LINE_STRIP) {
      if (warnings_)
        warnings_->push_back(file_ + ": " + element + ": mode " + std::to_string(prim.mode) +
                             " (points or lines) skipped: it has no area to light");
      return;
    }
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        prim.mode != TINYGLTF_MODE_TRIANGLE_FAN)
      throw SceneError(file_, element, "has mode " + std::to_string(prim.mode) + ", which glTF 2.0 does not define",
                       "use a mode from 0 to 6");
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end())
      throw SceneError(file_, element, "has no POSITION attribute", "give every triangle primitive positions");
    const std::vector<Vec3> local = readFloatVec3(model_, position->second, file_, "POSITION of " + element);
    std::vector<uint32_t> vertices;
    if (prim.indices >= 0) {
      vertices = readIndices(model_, prim.indices, file_, "indices of " + element);
    } else {
      vertices.resize(local.size());
      for (size_t i = 0; i < vertices.size(); ++i) vertices[i] = static_cast<uint32_t>(i);
    }
    for (size_t i = 0; i < vertices.size(); ++i)
      if (vertices[i] >= local.size())
        throw SceneError(file_, element,
                         "index " + std::to_string(i) + " is " + std::to_string(vertices[i]) +
                             ", out of range for its " + std::to_string(local.size()) + " positions",
                         "keep every index below the POSITION accessor's count");
    const std::vector<uint32_t> indices = triangleList(prim.mode, vertices, file_, element);
    const auto colour = prim.attributes.find("COLOR_0");
    std::vector<Rgb> colours;
    if (colour != prim.attributes.end())
      colours = readColours(model_, colour->second, file_, "COLOR_0 of " + element);
    if (colours.size() < local.size()) uncoloured_ = true;
    const int material = materialOf(prim, element);
    // A mirroring transform turns counter-clockwise into clockwise (glTF 2.0 spec, 3.7.4).
    const bool mirrored = glm::determinant(world) < 0.0;
    for (size_t i = 0; i < indices.size(); i += 3) {
      Polygon t{{}, material, element};
      std::array<Rgb, 3> colour;
      for (int k = 0; k < 3; ++k) {
        const uint32_t index = indices[i + (mirrored ? 2 - k : k)];
        t.vertices.push_back(Vec3(world * glm::dvec4(local[index], 1.0)));
        if (!withinCoordinateBound(t.vertices.back()))
          throw SceneError(file_, element + " (" + node + ")",
                           fmt::format("vertex {} lands at ({:g}, {:g}, {:g}) through the node transforms, farther "
                                       "than {:g} m from the origin, where lengths and areas overflow",
                                       index, t.vertices.back().x, t.vertices.back().y, t.vertices.back().z,
                                       kMaxCoordinate),
                           "check the scales and translations of the node and its parents (glTF is in metres)");
        if (!uncoloured_) colour[k] = colours[index];
      }
      triangles_.push_back(std::move(t));
      if (!uncoloured_) colours_.push_back(colour);
    }
  }

  // Scene material index: the file's own materials come first, the default grey after them.
  int materialOf(const tinygltf::Primitive& prim, const std::string& element) {
    if (prim.material < 0) {
      ++defaultMaterialUsers_;
      return static_cast<int>(model_.materials.size());
    }
    if (static_cast<size_t>(prim.material) >= model_.materials.size())
      throw SceneError(file_, element, "refers to material " + std::to_string(prim.material) + ", which does not exist",
                       "refer to an existing material, or none for the default grey");
    return prim.material;
  }

  const tinygltf::Model& model_;
  const std::string& file_;
  std::vector<std::string>* warnings_;
  std::vector<bool> onPath_;  // nodes on the current root-to-node path, to refuse cycles
  std::vector<Polygon> triangles_;
  std::vector<Light> lights_;
  int rangeIgnored_ = 0;
  NoteTally repairs_;  // rotations normalised
  std::vector<std::array<Rgb, 3>> colours_;
  bool uncoloured_ = false;
  int defaultMaterialUsers_ = 0;
};

// Each node's parent (-1 for none). glTF 2.0 (3.5.2) requires the hierarchy to be disjoint trees,
// each node with at most one parent: a node under two parents (or listed twice under one) is
// refused, as the traversal would visit it once per path (2^40 times down 40 such levels).
std::vector<int> parentNodes(const tinygltf::Model& model, const std::string& file) {
  std::vector<int> parent(model.nodes.size(), -1);
  for (size_t p = 0; p < model.nodes.size(); ++p)
    for (int c : model.nodes[p].children) {
      if (c < 0 || static_cast<size_t>(c) >= parent.size()) continue;  // refused when visited, by its referrer
      if (parent[c] >= 0) {
        const std::string label = nodeLabel(model, static_cast<int>(p));
        throw SceneError(file, nodeLabel(model, c),
                         "is " + (parent[c] == static_cast<int>(p) ? "listed twice among the children of " + label
                                  : "a child of both " + nodeLabel(model, parent[c]) + " and " + label) +
                             "; glTF 2.0 (3.5.2) allows a node at most one parent (the hierarchy must be disjoint trees)",
                         "give each parent its own node (nodes may share a mesh), and list each child once");
      }
      parent[c] = static_cast<int>(p);
    }
  return parent;
}

// The roots to draw: the default scene's, scene 0's when the file names no default (as viewers
// do), else every node no node has as a child. A scene's nodes must be distinct roots (glTF 2.0
// 3.5.2, and scene.nodes is uniqueItems): a node listed twice, or also some node's child, would be
// drawn twice. The hierarchy is checked (parentNodes) before anything is traversed.
std::vector<std::pair<int, std::string>> sceneRoots(const tinygltf::Model& model, const std::string& file) {
  const std::vector<int> parent = parentNodes(model, file);
  std::vector<std::pair<int, std::string>> roots;
  if (model.scenes.empty()) {
    for (size_t n = 0; n < model.nodes.size(); ++n)
      if (parent[n] < 0) roots.emplace_back(static_cast<int>(n), "nodes");
    return roots;
  }
  const int scene = std::max(model.defaultScene, 0);
  if (static_cast<size_t>(scene) >= model.scenes.size())
    throw SceneError(file, "scene", "the default scene " + std::to_string(scene) + " does not exist",
                     "set \"scene\" to an existing scene's index");
  const std::string label = "scene " + std::to_string(scene);
  std::vector<bool> listed(model.nodes.size(), false);
  for (int node : model.scenes[scene].nodes) {
    roots.emplace_back(node, label);
    if (node < 0 || static_cast<size_t>(node) >= model.nodes.size()) continue;  // refused when visited
    const std::string problem =
        listed[node] ? "is listed twice among the nodes of " + label
        : parent[node] >= 0 ? "is among the nodes of " + label + " and a child of " + nodeLabel(model, parent[node])
                            : "";
    if (!problem.empty())
      throw SceneError(file, nodeLabel(model, node),
                       problem + "; glTF 2.0 (3.5.2) lists each root node of a scene once, and only root nodes "
                                 "(it would be drawn twice)",
                       "list each root node once in the scene's nodes, and no node's child (it comes with its parent)");
    listed[node] = true;
  }
  return roots;
}

// A doubleSided surface receives and reflects on both sides: each of its triangles gets a reversed
// copy, set back along the copy's own normal by a hair (1e-6 of the scene's size, far above the
// projection's near depth) so that from either side the facing copy is the nearer one and the
// other lies behind the shooter.
void addBackFaces(const tinygltf::Model& model, std::vector<Polygon>& triangles) {
  const auto [low, high] = boundingBox(triangles);
  const double setBack = 1e-6 * glm::length(high - low);
  const size_t n = triangles.size();
  for (size_t i = 0; i < n; ++i) {
    const int m = triangles[i].material;
    if (m >= static_cast<int>(model.materials.size()) || !model.materials[m].doubleSided) continue;
    Polygon back = triangles[i];
    std::reverse(back.vertices.begin(), back.vertices.end());
    const Vec3 normal = newellNormal(back.vertices);
    if (!(glm::length(normal) > 0.0)) continue;  // degenerate: dropped when merging
    for (Vec3& v : back.vertices) v += setBack * glm::normalize(normal);
    back.origin += " (back face)";
    triangles.push_back(std::move(back));
  }
}

}  // namespace

GltfColouredTriangles readGltfColouredTriangles(const tinygltf::Model& model, const std::string& path) {
  TriangleCollector collector(model, path, nullptr);
  for (const auto& [node, referrer] : sceneRoots(model, path)) collector.visit(node, referrer);
  GltfColouredTriangles out{std::move(collector.triangles()), collector.colours(), false};
  for (const Material& m : convertGltfMaterials(model, path, nullptr)) out.emits = out.emits || m.emits();
  return out;
}

Scene importGltf(const std::string& path, std::vector<std::string>* warnings) {
  const tinygltf::Model model = loadGltfModel(path, warnings);
  Scene scene;
  scene.source = path;
  scene.upAxis = 1;  // glTF 2.0 spec, 3.4: +Y is up
  scene.materials = convertGltfMaterials(model, path, warnings);
  TriangleCollector collector(model, path, warnings);
  for (const auto& [node, referrer] : sceneRoots(model, path)) collector.visit(node, referrer);
  if (collector.defaultMaterialUsers() > 0) {
    scene.materials.push_back(defaultGltfMaterial());
    if (warnings)
      warnings->push_back(path + ": " + std::to_string(collector.defaultMaterialUsers()) +
                          " primitive(s) without a material get the material '" + scene.materials.back().name + "'");
  }
  scene.lights = collector.lights();
  if (warnings)
    for (const std::string& line : collector.repairs().lines()) warnings->push_back(line);
  if (collector.rangeIgnored() > 0 && warnings)
    warnings->push_back(path + ": " + std::to_string(collector.rangeIgnored()) +
                        " KHR_lights_punctual light(s) with a range: ignored, their light falls off with the inverse "
                        "square of distance all the way, as physical light does");
  addBackFaces(model, collector.triangles());
  MergeReport report;
  scene.polygons = mergeCoplanarTriangles(collector.triangles(), &report);
  if (report.degenerateDropped > 0 && warnings)
    warnings->push_back(path + ": " + std::to_string(report.degenerateDropped) +
                        " degenerate (zero-area) triangle(s) dropped");
  return scene;
}

}  // namespace radmesh
