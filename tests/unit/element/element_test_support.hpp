#pragma once
/// Helpers shared by the element unit tests: random distorted tetrahedra and states, every registry
/// model with parameters, and the observed order of a sequence of finite-difference errors.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "element/mini.hpp"
#include "material/registry.hpp"

namespace plisse::test {

/// A positively oriented, visibly distorted tetrahedron (edge lengths ~ `size` [mm], aspect up to
/// ~3), different for each seed.
inline std::array<Vec3d, 4> random_tet(unsigned seed, double size = 2.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::array<Vec3d, 4> X = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};
  for (auto& x : X) x += Vec3d(jitter(rng), jitter(rng), jitter(rng));
  const Mat3d stretch = (Vec3d(1.0, 0.6, 1.4)).asDiagonal();
  const Vec3d shift(jitter(rng) + 3.0, jitter(rng) - 1.0, jitter(rng));
  for (auto& x : X) x = size * (stretch * x + shift);
  if ((X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) < 0) std::swap(X[2], X[3]);
  return X;
}

/// A random element state: nodal displacements uniform in ±`u_fraction` × element size [mm],
/// nodal pressures uniform in ±`p_scale` [MPa].
inline mini::ElemVec random_state(unsigned seed, const mini::TetGeometry& g, double u_fraction,
                                  double p_scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  mini::ElemVec x;
  for (int i = 0; i < mini::kDofU; ++i) x(i) = u_fraction * g.size * unit(rng);
  for (int a = 0; a < mini::kDofP; ++a) x(mini::dof_p(a)) = p_scale * unit(rng);
  return x;
}

/// log2 slope between the last two errors of a sequence taken with h halved each time.
inline double observed_order(const std::vector<double>& errors) {
  const std::size_t n = errors.size();
  return std::log2(errors[n - 2] / errors[n - 1]);
}

/// Nodal displacements of the homogeneous deformation x = F0 X + c at the corners X (pressures 0).
inline mini::ElemVec homogeneous_state(const std::array<Vec3d, 4>& X, const Mat3d& F0,
                                       const Vec3d& c = Vec3d::Zero()) {
  mini::ElemVec x = mini::ElemVec::Zero();
  for (int a = 0; a < 4; ++a) x.segment<3>(mini::dof_u(a, 0)) = (F0 - Mat3d::Identity()) * X[a] + c;
  return x;
}

/// The rotation by `angle` about the unit `axis`.
inline Mat3d rotation(const Vec3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// A small tetrahedral mesh for multi-element tests.
struct PatchMesh {
  std::vector<Vec3d> nodes;              ///< [mm]
  std::vector<std::array<int, 4>> tets;  // positively oriented
  std::vector<bool> on_boundary;
};

/// [0, 1]³ split into n³ cells of 6 tetrahedra each (along each cell's main diagonal); interior
/// nodes moved randomly by up to 0.2 of a cell so that no element is a scaled copy of another.
inline PatchMesh distorted_cube(int n, unsigned seed) {
  PatchMesh m;
  auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2 / n, 0.2 / n);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const bool boundary = i == 0 || j == 0 || k == 0 || i == n || j == n || k == n;
        Vec3d x(double(i) / n, double(j) / n, double(k) / n);
        if (!boundary) x += Vec3d(jitter(rng), jitter(rng), jitter(rng));
        m.nodes.push_back(x);
        m.on_boundary.push_back(boundary);
      }
  const std::array<std::array<int, 3>, 6> orders = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& order : orders) {
          std::array<int, 3> c = {i, j, k};
          std::array<int, 4> tet;
          tet[0] = id(c[0], c[1], c[2]);
          for (int step = 0; step < 3; ++step) {
            ++c[order[step]];
            tet[step + 1] = id(c[0], c[1], c[2]);
          }
          const auto& X = m.nodes;
          if ((X[tet[1]] - X[tet[0]]).cross(X[tet[2]] - X[tet[0]]).dot(X[tet[3]] - X[tet[0]]) < 0)
            std::swap(tet[2], tet[3]);
          m.tets.push_back(tet);
        }
  return m;
}

/// Every registry model, with moduli of the order of 1 MPa; the fibre model's fibres lie along
/// (1, 0.5, 0) and along z. A model without an entry here fails the calling test.
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

}  // namespace plisse::test
