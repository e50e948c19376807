#pragma once
// Closed-form form factors from the radiation heat-transfer catalogues (Howell's C-11 and C-14),
// the references the solver's form factors are checked against.
#include <cmath>
#include <numbers>

namespace radmesh::test {

// Between directly opposed parallel rectangles a x b, a distance c apart (Howell C-11).
inline double parallelRectanglesFormFactor(double a, double b, double c) {
  const double X = a / c, Y = b / c;
  const double x1 = std::sqrt(1 + X * X), y1 = std::sqrt(1 + Y * Y);
  const double bracket = std::log(x1 * y1 / std::sqrt(1 + X * X + Y * Y)) + X * y1 * std::atan(X / y1) +
                         Y * x1 * std::atan(Y / x1) - X * std::atan(X) - Y * std::atan(Y);
  return 2.0 / (std::numbers::pi * X * Y) * bracket;
}

// From a rectangle of width w to a perpendicular one of height h sharing an edge of length l
// (Howell C-14).
inline double perpendicularRectanglesFormFactor(double w, double h, double l) {
  const double W = w / l, H = h / l;
  const double W2 = W * W, H2 = H * H, R = std::sqrt(W2 + H2);
  const double logTerm = std::log((1 + W2) * (1 + H2) / (1 + W2 + H2)) +
                         W2 * std::log(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2))) +
                         H2 * std::log(H2 * (1 + H2 + W2) / ((1 + H2) * (H2 + W2)));
  return (W * std::atan(1 / W) + H * std::atan(1 / H) - R * std::atan(1 / R) + 0.25 * logTerm) /
         (std::numbers::pi * W);
}

}  // namespace radmesh::test
