#pragma once
/// Patches of the shell triangle for its unit tests: flat 2-D patches (the triangle and its three
/// neighbours' opposite nodes, mirrored or distorted) and mapped onto surfaces (every registry
/// model: element_test_support.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "element/shell.hpp"
#include "element_test_support.hpp"
#include "material/registry.hpp"
#include "support/principal_neo_hookean.hpp"

namespace plisse::test {

using shell::PatchPositions;
using shell::PatchVec;
using shell::Vec2d;

/// A 2-D patch of size h [mm] (KL1, KL1b): the triangle (0, 0), (h, 0), (0.3 h, 0.9 h), each node
/// across a side at the mirror image of the triangle's node through the side's midpoint, and each
/// node beyond a neighbour's side at the mirror image of the neighbour's corner opposite it,
/// every one moved by up to `jitter` × h in each direction (0: the regular, mirrored patch).
inline std::array<Vec2d, shell::kPatchNodes> plane_patch(double h, double jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::array<Vec2d, shell::kPatchNodes> p = {Vec2d(0, 0), Vec2d(h, 0), Vec2d(0.3 * h, 0.9 * h)};
  for (int i = 0; i < 3; ++i) {
    p[3 + i] = p[(i + 1) % 3] + p[(i + 2) % 3] - p[i];
    p[3 + i] += jitter * h * Vec2d(unit(rng), unit(rng));
  }
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    p[shell::outer_slot(i, 0)] = p[3 + i] + p[k] - p[j];
    p[shell::outer_slot(i, 1)] = p[3 + i] + p[j] - p[k];
  }
  for (int n = 6; n < shell::kPatchNodes; ++n) p[n] += jitter * h * Vec2d(unit(rng), unit(rng));
  return p;
}

/// The patch mapped by a map from the plane to 3-D.
inline PatchPositions map_patch(const std::array<Vec2d, shell::kPatchNodes>& p,
                                const std::function<Vec3d(const Vec2d&)>& map) {
  PatchPositions X;
  for (int n = 0; n < shell::kPatchNodes; ++n) X[n] = map(p[n]);
  return X;
}

inline PatchVec to_vector(const PatchPositions& X) {
  PatchVec x;
  for (int n = 0; n < shell::kPatchNodes; ++n) x.segment<3>(3 * n) = X[n];
  return x;
}

/// Every slot a node but those across and beyond the sides `free` (an element on free edges).
inline shell::SlotKinds free_sides(std::initializer_list<int> free) {
  shell::SlotKinds slots = shell::all_nodes();
  for (int i : free) {
    const shell::SlotKinds one = shell::without_side(i);
    for (int n = 0; n < shell::kPatchNodes; ++n)
      if (one[n] == shell::Slot::missing) slots[n] = shell::Slot::missing;
  }
  return slots;
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
