#pragma once
// Comparing the mesh back end with the native one: shooters with varied viewpoints, item buffers
// pixel for pixel, form-factor rows and radiosity to a relative tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "solver/backends/form_factor_backend.h"
#include "solver/projection/item_buffer.h"
#include "solver/meshing/meshing.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"
#include "solver/io/scene_loader.h"

namespace radmesh::test {

struct MeshedScene {
  Scene scene;
  std::vector<Patch> patches;
};

// A built-in name or a scene file, meshed at the default cell.
inline MeshedScene meshedScene(const std::string& pathOrName) {
  MeshedScene m{loadScene(pathOrName), {}};
  m.patches = meshScene(m.scene);
  return m;
}

// The strongest emitter patch and a few others spread over the scene: varied viewpoints.
inline std::vector<int> someShooters(const Scene& scene, const std::vector<Patch>& patches, int count) {
  const int n = static_cast<int>(patches.size());
  auto emitted = [&](int j) {
    const Rgb e = scene.materials[patches[j].material].emittance;
    return e.r + e.g + e.b;
  };
  int brightest = 0;
  for (int j = 0; j < n; ++j)
    if (emitted(j) > emitted(brightest)) brightest = j;
  std::vector<int> shooters{brightest};
  for (int k = 1; k < count; ++k) shooters.push_back(static_cast<int>((static_cast<long long>(n) * k / count + 7) % n));
  return shooters;
}

inline ::testing::AssertionResult sameItemBuffer(const ItemBuffer& mesh, const ItemBuffer& native) {
  if (mesh.width != native.width || mesh.height != native.height)
    return ::testing::AssertionFailure() << "sizes differ";
  for (int row = 0; row < native.height; ++row)
    for (int column = 0; column < native.width; ++column) {
      const int q = native.index(column, row);
      if (mesh.items[q] != native.items[q] || mesh.inverseDepth[q] != native.inverseDepth[q])
        return ::testing::AssertionFailure()
               << "first difference at pixel (column " << column << ", row " << row << "): mesh item "
               << mesh.items[q] << " at 1/depth " << mesh.inverseDepth[q] << ", native item " << native.items[q]
               << " at 1/depth " << native.inverseDepth[q];
    }
  return ::testing::AssertionSuccess();
}

// Same receivers, form factors to `relative`, same back-face and captured fractions.
inline void expectSameRow(const FormFactorRow& mesh, const FormFactorRow& native, double relative) {
  ASSERT_EQ(mesh.shooter, native.shooter);
  ASSERT_EQ(mesh.receivers, native.receivers) << "shooter " << native.shooter;
  for (std::size_t k = 0; k < native.receivers.size(); ++k)
    ASSERT_NEAR(mesh.formFactors[k], native.formFactors[k], relative * native.formFactors[k])
        << "shooter " << native.shooter << " receiver " << native.receivers[k];
  EXPECT_NEAR(mesh.backFaces, native.backFaces, relative * std::max(native.backFaces, 1e-300));
  EXPECT_EQ(mesh.capturedFraction, native.capturedFraction);
}

// Every patch's B in every channel to `relative` of the reference (zero stays zero).
inline ::testing::AssertionResult sameRadiosity(const std::vector<Rgb>& got, const std::vector<Rgb>& reference,
                                                double relative) {
  if (got.size() != reference.size()) return ::testing::AssertionFailure() << "patch counts differ";
  for (std::size_t j = 0; j < reference.size(); ++j)
    for (int c = 0; c < 3; ++c)
      if (!(std::abs(got[j][c] - reference[j][c]) <= relative * std::max(1e-12, reference[j][c])))
        return ::testing::AssertionFailure() << "patch " << j << " channel " << c << ": " << got[j][c]
                                             << " against " << reference[j][c] << " (relative difference "
                                             << std::abs(got[j][c] - reference[j][c]) / reference[j][c] << ")";
  return ::testing::AssertionSuccess();
}

}  // namespace radmesh::test
