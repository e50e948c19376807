#include "solver/formfactors/direction_bins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "solver/formfactors/analytic_form_factor.h"
#include "solver/projection/hemicube.h"

namespace radmesh {

namespace {

struct BinFace {
  ProjectionFace face;
  int firstBin = 0;
};

std::vector<BinFace> binFaces(int n) {
  std::vector<BinFace> faces;
  int first = 0;
  for (const ProjectionFace& face : hemicubeFaces(n)) {
    faces.push_back({face, first});
    first += face.width * face.height;
  }
  return faces;
}

// The face a direction leaves through: the top, or the side along its largest horizontal axis.
int faceOf(const Vec3& d) {
  const double x = std::abs(d.x), y = std::abs(d.y);
  if (d.z >= std::max(x, y)) return 0;
  if (x >= y) return d.x >= 0.0 ? 1 : 2;
  return d.y >= 0.0 ? 3 : 4;
}

// The pixel's corners at depth 1, in the patch's frame.
std::array<Vec3, 4> binCorners(const ProjectionFace& face, int column, int row) {
  const double a0 = face.a0 + column * face.pixelWidth(), a1 = a0 + face.pixelWidth();
  const double b0 = face.b0 + row * face.pixelHeight(), b1 = b0 + face.pixelHeight();
  return {face.toLocal({a0, b0}), face.toLocal({a1, b0}), face.toLocal({a1, b1}), face.toLocal({a0, b1})};
}

// The part of a convex polygon on the side of the plane through the origin where dot(m, p) >= 0.
std::vector<Vec3> clipAtOrigin(const std::vector<Vec3>& polygon, const Vec3& m) {
  std::vector<Vec3> out;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Vec3& p = polygon[k];
    const Vec3& q = polygon[(k + 1) % polygon.size()];
    const double dp = glm::dot(m, p), dq = glm::dot(m, q);
    if (dp >= 0.0) out.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
  }
  return out.size() >= 3 ? out : std::vector<Vec3>{};
}

// The normal of the plane through the origin and the face's line coordinate[k] = value, pointing
// to larger values (k: 0 along a, 1 along b).
Vec3 lineNormal(const ProjectionFace& face, int k, double value) {
  Vec3 onFace{0.0};  // in face coordinates (a, b, depth): a - value * depth >= 0
  onFace[k] = 1.0;
  onFace[2] = -value;
  Vec3 local{0.0};
  for (int i = 0; i < 3; ++i) local[face.axis[i]] = face.sign[i] * onFace[i];
  return local;
}

}  // namespace

int directionBinCount(int n) {
  if (n <= 1) return 1;
  return n * n + 4 * n * ((n + 1) / 2);
}

int directionBin(int n, const Vec3& local) {
  if (n <= 1) return 0;
  const std::vector<BinFace> faces = binFaces(n);
  const BinFace& f = faces[faceOf(local)];
  const Vec3 onFace = toFace(f.face, local);
  auto cell = [](double at, double from, double size, int count) {
    return std::clamp(static_cast<int>(std::floor((at - from) / size)), 0, count - 1);
  };
  const int column = cell(onFace.x / onFace.z, f.face.a0, f.face.pixelWidth(), f.face.width);
  const int row = cell(onFace.y / onFace.z, f.face.b0, f.face.pixelHeight(), f.face.height);
  return f.firstBin + row * f.face.width + column;
}

double directionBinFormFactor(int n, int bin) {
  if (n <= 1) return 1.0;
  for (const BinFace& f : binFaces(n)) {
    const int pixels = f.face.width * f.face.height;
    if (bin < f.firstBin + pixels) {
      const std::array<Vec3, 4> corners = binCorners(f.face, (bin - f.firstBin) % f.face.width,
                                                     (bin - f.firstBin) / f.face.width);
      return pointToPolygonFormFactor(corners);
    }
  }
  return 0.0;
}

void splitOverDirectionBins(int n, std::span<const Vec3> polygon, const std::function<void(int, double)>& add) {
  std::vector<Vec3> above = clipAtOrigin({polygon.begin(), polygon.end()}, Vec3(0, 0, 1));
  if (n <= 1) {
    if (!above.empty()) add(0, pointToPolygonFormFactor(above));
    return;
  }
  for (const BinFace& f : binFaces(n)) {
    const ProjectionFace& face = f.face;
    // The part on this face, and the rows and columns its corners reach: only those are cut.
    std::vector<Vec3> onFace = above;
    for (int k : {0, 1}) {
      const double lo = k == 0 ? face.a0 : face.b0, hi = k == 0 ? face.a1 : face.b1;
      onFace = clipAtOrigin(clipAtOrigin(onFace, lineNormal(face, k, lo)), -lineNormal(face, k, hi));
    }
    if (onFace.empty()) continue;
    std::array<int, 2> first{face.width - 1, face.height - 1}, last{0, 0};
    for (const Vec3& p : onFace) {
      const Vec3 q = toFace(face, p);
      for (int k : {0, 1}) {
        const double from = k == 0 ? face.a0 : face.b0, size = k == 0 ? face.pixelWidth() : face.pixelHeight();
        const int count = k == 0 ? face.width : face.height;
        const int at = q.z > 0.0 ? std::clamp(static_cast<int>(std::floor((q[k] / q.z - from) / size)), 0, count - 1) : -1;
        first[k] = at < 0 ? 0 : std::min(first[k], at);
        last[k] = at < 0 ? count - 1 : std::max(last[k], at);
      }
    }
    for (int row = first[1]; row <= last[1]; ++row) {
      const double b0 = face.b0 + row * face.pixelHeight();
      std::vector<Vec3> band = clipAtOrigin(clipAtOrigin(onFace, lineNormal(face, 1, b0)),
                                            -lineNormal(face, 1, b0 + face.pixelHeight()));
      if (band.empty()) continue;
      for (int column = first[0]; column <= last[0]; ++column) {
        const double a0 = face.a0 + column * face.pixelWidth();
        std::vector<Vec3> part = clipAtOrigin(clipAtOrigin(band, lineNormal(face, 0, a0)),
                                              -lineNormal(face, 0, a0 + face.pixelWidth()));
        if (!part.empty()) add(f.firstBin + row * face.width + column, pointToPolygonFormFactor(part));
      }
    }
  }
}

}  // namespace radmesh
