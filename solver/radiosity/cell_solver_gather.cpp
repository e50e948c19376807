// The building's radiosity and elements read from the cells that hold them, over every process:
// the cells solve's output, apart from its rounds (cell_solver.cpp).
#include <vector>

#include "solver/radiosity/cell_solver.h"
#include "solver/radiosity/cell_solver_state.h"

namespace radmesh {

// Per building patch, what `perCell` gives for each cell's own patches, from every process.
template <typename PerCell>
std::vector<Rgb> CellSolver::State::gatherPatches(PerCell perCell) const {
  std::vector<std::vector<double>> values(cells.size());
  for (size_t c = 0; c < cells.size(); ++c) {
    if (!owns(static_cast<int>(c))) {
      values[c].resize(3 * cells[c].buildingPatch.size());
      continue;
    }
    const std::vector<Rgb>& b = perCell(*cells[c].solver);
    for (size_t j = 0; j < cells[c].buildingPatch.size(); ++j) values[c].insert(values[c].end(), {b[j].r, b[j].g, b[j].b});
  }
  if (ranks) ranks->shareCells(owner, values);
  std::vector<Rgb> out(patches.size(), Rgb(0.0));
  for (size_t c = 0; c < cells.size(); ++c)
    for (size_t j = 0; j < cells[c].buildingPatch.size(); ++j)
      out[cells[c].buildingPatch[j]] = Rgb(values[c][3 * j], values[c][3 * j + 1], values[c][3 * j + 2]);
  return out;
}

std::vector<Rgb> CellSolver::radiosity() const {
  return state_->gatherPatches([](const ProgressiveSolver& s) { return s.radiosity(); });
}

std::vector<Rgb> CellSolver::displayRadiosity() const {
  return state_->gatherPatches([](const ProgressiveSolver& s) { return s.displayRadiosity(); });
}

// The cells' receivers of the building's patches, in the building's order: for each patch, its
// cell's `width` values per element of it (what `write(cell, element, out)` appends), from every
// process, handed to `read(patch, values)`. A cell's stream holds, own patch by own patch (in the
// building's order), its element count, then its elements' values.
template <typename Write, typename Read>
void CellSolver::State::gatherElements(size_t width, Write write, Read read) const {
  const size_t n = cells.size();
  std::vector<std::vector<double>> values(n), sizes(n, std::vector<double>(1, 0.0));
  for (size_t c = 0; c < n; ++c) {
    if (!owns(static_cast<int>(c))) continue;
    const ProgressiveSolver& solver = *cells[c].solver;
    for (size_t k = 0; k < cells[c].buildingPatch.size(); ++k) {
      const std::vector<int> elements = solver.elementsOf({static_cast<int>(k)});
      values[c].push_back(static_cast<double>(elements.size()));
      for (int e : elements) write(c, e, values[c]);
    }
    sizes[c][0] = static_cast<double>(values[c].size());
  }
  if (ranks) {  // the streams' lengths first, as CellRanks::shareCells needs them on every process
    ranks->shareCells(owner, sizes);
    for (size_t c = 0; c < n; ++c) values[c].resize(static_cast<size_t>(sizes[c][0]));
    ranks->shareCells(owner, values);
  }
  std::vector<size_t> at(n, 0);
  for (size_t j = 0; j < patches.size(); ++j) {
    const std::vector<double>& stream = values[cellOf[j]];
    size_t& k = at[cellOf[j]];
    const size_t count = static_cast<size_t>(stream[k++]);
    for (size_t e = 0; e < count; ++e, k += width) read(j, &stream[k]);
  }
}

template <typename PerElement>
std::vector<Rgb> CellSolver::State::gatherElementRadiosity(PerElement perElement) const {
  std::vector<std::vector<Rgb>> own(cells.size());
  for (size_t c = 0; c < cells.size(); ++c)
    if (owns(static_cast<int>(c))) own[c] = perElement(*cells[c].solver);
  std::vector<Rgb> out;
  gatherElements(
      3,
      [&](size_t c, int e, std::vector<double>& to) {
        const Rgb& b = own[c][static_cast<size_t>(e)];
        to.insert(to.end(), {b.r, b.g, b.b});
      },
      [&](size_t, const double* v) { out.emplace_back(v[0], v[1], v[2]); });
  return out;
}

Elements CellSolver::elements() const {
  const State& s = *state_;
  if (s.options.subdivide == Subdivide::Off) return patchesAsElements(s.patches);
  Elements out;
  out.first.assign(s.patches.size() + 1, 0);
  // An element: its patch's normal, frame, material and polygon, its own corners, centroid and area.
  s.gatherElements(
      17,
      [&](size_t c, int e, std::vector<double>& to) {
        const Patch& p = s.cells[c].solver->elements()[static_cast<size_t>(e)];
        to.push_back(p.vertexCount);
        for (const Vec3& v : p.vertices) to.insert(to.end(), {v.x, v.y, v.z});
        to.insert(to.end(), {p.centroid.x, p.centroid.y, p.centroid.z, p.areaM2});
      },
      [&](size_t j, const double* v) {
        Patch& p = out.elements.emplace_back(s.patches[j]);
        p.vertexCount = static_cast<int>(v[0]);
        for (size_t k = 0; k < 4; ++k) p.vertices[k] = Vec3(v[1 + 3 * k], v[2 + 3 * k], v[3 + 3 * k]);
        p.centroid = Vec3(v[13], v[14], v[15]);
        p.areaM2 = v[16];
        out.patchOf.push_back(static_cast<int>(j));
        out.first[j + 1] = static_cast<int>(out.elements.size());
      });
  return out;
}

std::vector<Rgb> CellSolver::elementRadiosity() const {
  if (state_->options.subdivide == Subdivide::Off) return radiosity();
  return state_->gatherElementRadiosity([](const ProgressiveSolver& s) { return s.elementRadiosity(); });
}

std::vector<Rgb> CellSolver::displayElementRadiosity() const {
  if (state_->options.subdivide == Subdivide::Off) return displayRadiosity();
  return state_->gatherElementRadiosity([](const ProgressiveSolver& s) { return s.displayElementRadiosity(); });
}

}  // namespace radmesh
