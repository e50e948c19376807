// Adaptive subdivision (--subdivide adaptive): after each iteration's shots, the elements across
// which the light changes split in four (solver/radiosity/adaptive_split.h), and the children
// receive this iteration's shots anew (or every shot so far), until nothing more splits. What an
// element received in earlier iterations its children inherit (the parent's radiosity); later
// shots correct them.
#include <algorithm>

#include "parallel/thread_pool.h"
#include "solver/formfactors/light_rows.h"
#include "solver/formfactors/near_field.h"
#include "solver/projection/projection.h"
#include "solver/radiosity/adaptive_split.h"
#include "solver/radiosity/progressive_solver_state.h"

namespace radmesh {

using solver_state::channelSum;


void ProgressiveSolver::State::refine(IterationRecord& record) {
  for (;;) {
    const size_t n = elements.elements.size();
    std::vector<char> split(n, 0);
    std::vector<double> reflected(n);
    for (size_t e = 0; e < n; ++e)
      reflected[e] = channelSum(elementRadiosity[e] - scene.materials[elements.elements[e].material].emittance);
    if (!backend->markContrast(adjacency.neighbours, reflected, options.splitContrast,
                               [&](int e) { return splittable(elements.elements[e], options.minElementM); }, split))
      markContrast(elements, adjacency.neighbours, reflected, options.splitContrast, options.minElementM, split);
    if (options.splitShadows) {
      if (!occluders) occluders.emplace(patches);
      size_t r = 0;  // rows holds the patch shots' rows, in order
      for (const Shot& shot : shots) {
        if (shot.patch < 0) continue;
        const FormFactorRow& row = rows[r++];
        if (channelSum(shot.power) >= kShadowShotFraction * firstShotPowerW)
          backend->testReceivers(row, kShadowTestFlops, kRayPatchFlops * static_cast<double>(patches.size()),
                                 [&](size_t k) {
                                   return markShadowEdge(row, k, patches[shot.patch], elements, *occluders,
                                                         options.minElementM, split);
                                 });
      }
    }
    const auto count = static_cast<size_t>(std::count(split.begin(), split.end(), 1));
    // No cap here: checkElementBudget bounded every split this can make (solver/meshing/elements.h).
    if (count == 0) return;
    record.elementsSplit += static_cast<int>(count);
    const std::vector<Rgb> parentRadiosity = std::move(elementRadiosity), parentGain = iterationGain;
    const std::vector<int> origin = splitElements(elements, split);
    backend->receiversSplit(origin);
    if (elementNear) elementNear->receiversSplit(origin, split);
    nearPairs.assign(patches.size(), {});
    splitAdjacency(adjacency, elements, origin, split);
    cache.renumberReceivers(newIndices(origin, split));
    regather(origin, split, parentRadiosity, parentGain);
  }
}

// The children of split elements. Each starts with its parent's radiosity; what the parent
// received from the shots regathered (this iteration's, or with --split-regather all every shot so
// far) the children share by their own form factors from those shots (shot again onto them),
// scaled per channel so that together they receive exactly what the parent did. The patch's
// radiosity, unshot power and the ledger do not change: splitting moves light within a patch, and
// never creates or loses any.
void ProgressiveSolver::State::regather(const std::vector<int>& origin, const std::vector<char>& split,
                                        const std::vector<Rgb>& parentRadiosity, const std::vector<Rgb>& parentGain) {
  const size_t n = elements.elements.size();
  std::vector<Shot> sources = shots;
  if (options.splitRegatherAll) {
    sources.clear();
    for (size_t p = 0; p < patches.size(); ++p)
      if (channelSum(shotTotal[p]) > 0.0) sources.push_back({static_cast<int>(p), -1, shotTotal[p]});
    const std::vector<Rgb>& lights = regatheredLightPower();
    for (size_t k = 0; lightsShot && k < lights.size(); ++k)
      if (channelSum(lights[k]) > 0.0) sources.push_back({-1, static_cast<int>(k), lights[k]});
  }
  std::vector<int> shooters;
  for (const Shot& shot : sources)
    if (shot.patch >= 0) shooters.push_back(shot.patch);
  std::vector<FormFactorRow> fresh;
  if (!shooters.empty()) computeFreshRows(shooters, fresh);
  std::vector<Rgb> gain(n, Rgb(0.0));
  const auto add = [&](const FormFactorRow& row, const Rgb& power) {
    for (size_t r = 0; r < row.receivers.size(); ++r) {
      const int e = row.receivers[r];
      if (split[origin[e]])
        gain[e] += rho[elements.patchOf[e]] * power * row.formFactors[r] / elements.elements[e].areaM2;
    }
  };
  if (plan.interreflection) {  // else nothing is reflected: B stays as emitted
    ThreadPool pool(options.threads);
    size_t r = 0;
    for (const Shot& shot : sources) {
      if (shot.patch >= 0)
        add(fresh[r++], shot.power);
      else
        add(lightRowOnElements(shot.light, pool), shot.power);
    }
  }
  elementRadiosity.resize(n);
  const std::vector<Rgb> parentIterationGain = std::move(iterationGain);
  iterationGain.assign(n, Rgb(0.0));
  for (size_t first = 0; first < n;) {
    const int parent = origin[first];
    size_t last = first + 1;
    while (last < n && origin[last] == parent) ++last;
    // What the children share anew: this iteration's light, or all the parent reflected.
    const Rgb shared = options.splitRegatherAll
        ? parentRadiosity[parent] - scene.materials[elements.elements[first].material].emittance
        : parentGain[parent];
    Rgb area(0.0), gathered(0.0);
    for (size_t c = first; c < last; ++c) {
      area += Rgb(elements.elements[c].areaM2);
      gathered += gain[c] * elements.elements[c].areaM2;
    }
    const Rgb target = shared * area;
    for (size_t c = first; c < last; ++c) {
      Rgb share = shared;  // unsplit, or nothing gathered: the parent's, evenly
      if (split[parent])
        for (int k = 0; k < 3; ++k)
          if (gathered[k] > 0.0) share[k] = gain[c][k] * (target[k] / gathered[k]);
      elementRadiosity[c] = parentRadiosity[parent] - shared + share;
      iterationGain[c] = options.splitRegatherAll ? parentIterationGain[parent] : share;
    }
    first = last;
  }
  // This iteration's rows, over the new elements, for the shadow criterion's next look.
  std::vector<FormFactorRow> current;
  for (const Shot& shot : shots)
    if (shot.patch >= 0)
      current.push_back(*std::find_if(fresh.begin(), fresh.end(), [&](const FormFactorRow& row) { return row.shooter == shot.patch; }));
  rows = std::move(current);
  // They are what the back end would compute now: the cache keeps them for the shooters' next shots.
  if (options.formFactorCacheBytes > 0)
    for (const FormFactorRow& row : rows) {
      cache.erase(row.shooter);
      cache.insert(row);
    }
}

FormFactorRow ProgressiveSolver::State::lightRowOnElements(int light, ThreadPool& pool) const {
  if (buildingLightRow) return buildingLightRow(light, elements.elements);
  return lightRow(scene, scene.lights[light], elements.elements, options.resolution, sceneNearDepth(patches), pool);
}

// A cells solve's lights arrived before the first step (receiveLight): as the whole solve's first
// iteration, split where they changed the light and regather them onto the children.
void ProgressiveSolver::splitAfterLights(std::vector<Rgb> powers, LightRowOver again) {
  State& s = *state_;
  if (!s.adaptive() || !s.history.empty()) return;
  s.buildingLightPower = std::move(powers);
  s.buildingLightRow = std::move(again);
  s.lightsShot = true;
  s.shots.clear();
  for (size_t k = 0; k < s.buildingLightPower.size(); ++k)
    if (channelSum(s.buildingLightPower[k]) > 0.0) s.shots.push_back({-1, static_cast<int>(k), s.buildingLightPower[k]});
  s.rows.clear();  // the shadow criterion reads patch shots' rows: lights have none
  IterationRecord lights;
  s.refine(lights);
  s.lightSplits = lights.elementsSplit;
}

}  // namespace radmesh
