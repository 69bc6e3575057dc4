#pragma once
/// Patches of the shell triangle for its unit tests: flat 2-D patches (the triangle and its three
/// neighbours' opposite nodes, mirrored or distorted) and mapped onto surfaces (every registry
/// model: element_test_support.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "element/shell.hpp"
#include "element_test_support.hpp"
#include "material/registry.hpp"

namespace plisse::test {

using shell::PatchPositions;
using shell::PatchVec;
using shell::Vec2d;

/// A 2-D patch of size h [mm] (KL1): the triangle (0, 0), (h, 0), (0.3 h, 0.9 h) and each
/// opposite node at the mirror image of the triangle's node through the side's midpoint, moved
/// by up to `jitter` × h in each direction (0: the regular, mirrored patch).
inline std::array<Vec2d, 6> plane_patch(double h, double jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::array<Vec2d, 6> p = {Vec2d(0, 0), Vec2d(h, 0), Vec2d(0.3 * h, 0.9 * h)};
  for (int i = 0; i < 3; ++i) {
    p[3 + i] = p[(i + 1) % 3] + p[(i + 2) % 3] - p[i];
    p[3 + i] += jitter * h * Vec2d(unit(rng), unit(rng));
  }
  return p;
}

/// The patch mapped by a map from the plane to 3-D.
inline PatchPositions map_patch(const std::array<Vec2d, 6>& p,
                                const std::function<Vec3d(const Vec2d&)>& map) {
  PatchPositions X;
  for (int n = 0; n < 6; ++n) X[n] = map(p[n]);
  return X;
}

inline PatchVec to_vector(const PatchPositions& X) {
  PatchVec x;
  for (int n = 0; n < 6; ++n) x.segment<3>(3 * n) = X[n];
  return x;
}

/// A curved reference patch: a plane patch of size 1 mm, distorted, on the doubly curved surface
/// z = 0.3 x² - 0.2 x y + 0.15 y², turned out of the coordinate planes and moved away from the
/// origin.
inline PatchPositions curved_patch(unsigned seed) {
  const Mat3d R = Eigen::AngleAxisd(0.4, Vec3d(1, 2, 0.5).normalized()).toRotationMatrix();
  return map_patch(plane_patch(1.0, 0.25, seed), [&](const Vec2d& q) {
    const double z = 0.3 * q.x() * q.x() - 0.2 * q.x() * q.y() + 0.15 * q.y() * q.y();
    return Vec3d(R * Vec3d(q.x(), q.y(), z) + Vec3d(2.0, -1.0, 0.5));
  });
}

}  // namespace plisse::test
