#pragma once
/// Patches of the shell triangle for its unit tests: flat 2-D patches (the triangle and its three
/// neighbours' opposite nodes, mirrored or distorted), mapped onto surfaces, and every registry
/// model with parameters of the order of 1 MPa.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "element/shell.hpp"
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

/// Every registry model, with moduli of the order of 1 MPa; the fibre model's fibres lie in the
/// plane of curved_patch's surface near the triangle, and along its normal.
inline std::vector<AnyMaterial> every_material() {
  const std::map<std::string, MaterialValues> values = {
      {"neo-hookean", {{"c1", 0.5}}},
      {"mooney-rivlin", {{"c1", 0.35}, {"c2", 0.15}}},
      {"fung", {{"mu", 1.0}, {"gamma", 1.5}}},
      {"yeoh", {{"c1", 0.5}, {"c2", -0.05}, {"c3", 0.02}}},
      {"gent", {{"mu", 1.0}, {"jm", 20.0}}},
      {"arruda-boyce", {{"mu", 1.0}, {"lambda_m", 3.0}}},
      {"ogden",
       {{"mu1", 0.6},
        {"alpha1", 1.3},
        {"mu2", 0.01},
        {"alpha2", 5.0},
        {"mu3", -0.02},
        {"alpha3", -2.0}}},
      {"fibre-reinforced",
       {{"c1", 0.4}, {"k1", 1.0}, {"k2", 0.5}, {"a1_x", 1.0}, {"a1_y", 0.5}, {"a2_z", 1.0}}}};
  std::vector<AnyMaterial> out;
  for (const MaterialModelInfo& info : material_models()) {
    EXPECT_EQ(values.count(info.name), 1u) << "no parameters for " << info.name;
    if (values.count(info.name)) out.push_back(make_material(info.name, values.at(info.name)));
  }
  return out;
}

/// log2 slope between the last two errors of a sequence taken with h halved each time.
inline double observed_order(const std::vector<double>& errors) {
  const std::size_t n = errors.size();
  return std::log2(errors[n - 2] / errors[n - 1]);
}

}  // namespace plisse::test
