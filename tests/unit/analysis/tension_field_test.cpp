// Tension-field state on a layered spherical shell with synthetic per-element Cauchy stresses:
// biaxial tension is taut, meridional tension with hoop compression is wrinkled, compression is
// slack; regions mixed by latitude give their exact counts; the column average (volume- and
// J-weighted) decides, not one layer; rigid rotations change nothing.
#include "analysis/tension_field.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "analysis/surface_columns.hpp"
#include "analysis/wrinkle_rings.hpp"
#include "core/error.hpp"
#include "fixtures/shells.hpp"

namespace plisse {
namespace {

constexpr int kLayers = 3;

struct Shell {
  Mesh mesh;
  std::vector<std::array<int, 3>> outer;
  std::vector<int> column;  ///< from the prism structure, independent of assign_columns
};

const Shell& shell() {
  static const Shell s = [] {
    Shell out;
    out.mesh = test::sphere_shell(Symmetry::quarter, 10.0, 1.0, kLayers, 1.0);
    out.outer = tagged_triangles(out.mesh, "outer");
    out.column = test::prism_columns(out.mesh, kLayers, out.outer);
    return out;
  }();
  return s;
}

Vec3d triangle_centroid(const Shell& s, int t) {
  const auto& tri = s.outer[static_cast<std::size_t>(t)];
  return (s.mesh.nodes[tri[0]] + s.mesh.nodes[tri[1]] + s.mesh.nodes[tri[2]]) / 3.0;
}

/// sigma = s_m e_phi e_phi + s_h e_theta e_theta (meridional, hoop) at the point X of the sphere
/// (polar axis y), plane stress in the tangent plane.
Mat3d membrane_stress(const Vec3d& X, double s_m, double s_h) {
  const Vec3d er = X.normalized();
  Vec3d hoop = Vec3d::UnitY().cross(er);
  hoop = hoop.norm() > 1e-12 ? Vec3d(hoop.normalized()) : Vec3d::UnitX();
  const Vec3d meridian = hoop.cross(er);
  return s_m * meridian * meridian.transpose() + s_h * hoop * hoop.transpose();
}

/// Per-element stress from a function of (the outer triangle of its column, its layer).
std::vector<Mat3d> stress_field(const Shell& s, const std::function<Mat3d(int, int)>& f) {
  std::vector<Mat3d> sigma;
  for (std::size_t e = 0; e < s.mesh.tets.size(); ++e)
    sigma.push_back(f(s.column[e], test::tet_layer(s.mesh, kLayers, s.mesh.tets[e])));
  return sigma;
}

TensionField run(const Shell& s, const std::vector<Mat3d>& sigma, const std::vector<double>& J = {},
                 const TensionFieldSettings& o = {}, const std::vector<Vec3d>& u = {}) {
  const std::vector<Vec3d> zero(s.mesh.nodes.size(), Vec3d::Zero());
  return compute_tension_field(s.mesh.nodes, s.mesh.tets, s.outer, s.column, u.empty() ? zero : u,
                               sigma, J, o);
}

int n_tets() { return shell().mesh.n_tets(); }
int n_tri() { return static_cast<int>(shell().outer.size()); }

TEST(TensionField, UniformStatesEverywhere) {
  const Shell& s = shell();
  const auto uniform = [&](double s_m, double s_h) {
    return stress_field(
        s, [&](int t, int) { return membrane_stress(triangle_centroid(s, t), s_m, s_h); });
  };
  const TensionField biaxial = run(s, uniform(1.0, 0.8));
  EXPECT_EQ(biaxial.n_elements, (std::array<int, 3>{n_tets(), 0, 0}));
  EXPECT_EQ(biaxial.n_triangles, (std::array<int, 3>{n_tri(), 0, 0}));
  // Principal values: the tangent plane of a flat triangle is within ~h/R of the sphere's, so
  // the projected values are within (h/R)^2 ~ 1 % of (1, 0.8).
  for (const auto& p : biaxial.principal_stress) {
    EXPECT_NEAR(p[0], 1.0, 0.02);
    EXPECT_NEAR(p[1], 0.8, 0.02);
  }
  EXPECT_NEAR(biaxial.tolerance, 1e-6 * 1.0, 2e-8);  // default: 1e-6 max |sigma_1|

  const TensionField uniaxial = run(s, uniform(1.0, -0.5));  // hoop compression
  EXPECT_EQ(uniaxial.n_elements, (std::array<int, 3>{0, n_tets(), 0}));
  EXPECT_EQ(uniaxial.n_triangles, (std::array<int, 3>{0, n_tri(), 0}));
  for (MembraneState st : uniaxial.element_state) EXPECT_EQ(st, MembraneState::wrinkled);

  const TensionField compressed = run(s, uniform(-1.0, -0.3));
  EXPECT_EQ(compressed.n_elements, (std::array<int, 3>{0, 0, n_tets()}));
  EXPECT_EQ(compressed.n_triangles, (std::array<int, 3>{0, 0, n_tri()}));

  // A stress normal to the membrane only (sigma_rr) has no in-plane part: slack.
  const auto normal_only = stress_field(s, [&](int t, int) {
    const Vec3d er = triangle_centroid(s, t).normalized();
    return Mat3d(5.0 * er * er.transpose());
  });
  TensionFieldSettings o;
  o.tolerance = 0.1;  // the in-plane leak of 5 e_r e_r is 5 (angle n, e_r)^2 ~ 5 (h/R)^2 / 3 < 0.1
  EXPECT_EQ(run(s, normal_only, {}, o).n_triangles, (std::array<int, 3>{0, 0, n_tri()}));
}

TEST(TensionField, MixedRegionsGiveTheirCounts) {
  const Shell& s = shell();
  // Latitude bands by the outer triangle's centroid: y > 3 taut, -3 <= y <= 3 wrinkled,
  // y < -3 slack (the quarter model spans y in [-11, 11]).
  const auto expected = [&](int t) {
    const double y = triangle_centroid(s, t).y();
    return y > 3.0 ? 0 : y >= -3.0 ? 1 : 2;
  };
  const auto sigma = stress_field(s, [&](int t, int) {
    const Vec3d X = triangle_centroid(s, t);
    switch (expected(t)) {
      case 0:
        return membrane_stress(X, 2.0, 1.0);
      case 1:
        return membrane_stress(X, 2.0, -1.0);
      default:
        return membrane_stress(X, -2.0, -1.0);
    }
  });
  std::array<int, 3> count{};
  for (int t = 0; t < n_tri(); ++t) ++count[static_cast<std::size_t>(expected(t))];
  ASSERT_GT(count[0], 0);
  ASSERT_GT(count[1], 0);
  ASSERT_GT(count[2], 0);
  const TensionField tf = run(s, sigma);
  EXPECT_EQ(tf.n_triangles, count);
  const int per_column = 3 * kLayers;  // three tetrahedra per prism and layer
  EXPECT_EQ(tf.n_elements, (std::array<int, 3>{per_column * count[0], per_column * count[1],
                                               per_column * count[2]}));
  for (int t = 0; t < n_tri(); ++t)
    EXPECT_EQ(static_cast<int>(tf.triangle_state[static_cast<std::size_t>(t)]), expected(t));
  for (std::size_t e = 0; e < tf.element_state.size(); ++e)
    EXPECT_EQ(tf.element_state[e], tf.triangle_state[static_cast<std::size_t>(s.column[e])]);

  // Same answer through the Mesh overload, which finds the columns itself.
  const TensionField by_mesh = compute_tension_field(
      s.mesh, std::vector<Vec3d>(s.mesh.nodes.size(), Vec3d::Zero()), sigma, {});
  EXPECT_EQ(by_mesh.n_triangles, count);
  EXPECT_EQ(by_mesh.element_state, tf.element_state);
}

TEST(TensionField, TheVolumeWeightedColumnAverageDecides) {
  const Shell& s = shell();
  // Hoop stress -1, 0.5, 2 in layers 0 (inner), 1, 2: the inner layer is compressed, the
  // average hoop stress (about (-1 + 0.5 + 2)/3 = 0.5, outer layers weigh a bit more) is not.
  const double hoop[kLayers] = {-1.0, 0.5, 2.0};
  const auto sigma = stress_field(s, [&](int t, int layer) {
    return membrane_stress(triangle_centroid(s, t), 1.0, hoop[layer]);
  });
  EXPECT_EQ(run(s, sigma).n_triangles, (std::array<int, 3>{n_tri(), 0, 0}));
  // Deformed-volume weights J V0: an inner layer ten times as large pulls the average to
  // (-10 + 0.5 + 2)/12 < 0: wrinkled.
  std::vector<double> J;
  for (const auto& t : s.mesh.tets)
    J.push_back(test::tet_layer(s.mesh, kLayers, t) == 0 ? 10.0 : 1.0);
  EXPECT_EQ(run(s, sigma, J).n_triangles, (std::array<int, 3>{0, n_tri(), 0}));
}

TEST(TensionField, ARigidRotationChangesNothing) {
  const Shell& s = shell();
  const Mat3d Q = Eigen::AngleAxisd(1.1, Vec3d(1, 2, -0.5).normalized()).toRotationMatrix();
  const auto sigma = stress_field(s, [&](int t, int) {
    const double y = triangle_centroid(s, t).y();
    return membrane_stress(triangle_centroid(s, t), 1.0, y > 0 ? 0.5 : -0.5);
  });
  std::vector<Mat3d> rotated;
  for (const auto& m : sigma) rotated.push_back(Q * m * Q.transpose());
  std::vector<Vec3d> u;
  for (const auto& X : s.mesh.nodes) u.push_back(Q * X - X);
  const TensionField a = run(s, sigma), b = run(s, rotated, {}, {}, u);
  EXPECT_EQ(a.triangle_state, b.triangle_state);
  for (std::size_t t = 0; t < a.principal_stress.size(); ++t) {
    EXPECT_NEAR(a.principal_stress[t][0], b.principal_stress[t][0], 1e-12);
    EXPECT_NEAR(a.principal_stress[t][1], b.principal_stress[t][1], 1e-12);
  }
}

TEST(TensionField, AStatedToleranceIsUsed) {
  const Shell& s = shell();
  const auto sigma = stress_field(
      s, [&](int t, int) { return membrane_stress(triangle_centroid(s, t), 1.0, 0.8); });
  TensionFieldSettings o;
  o.tolerance = 0.9;  // sigma_2 ~ 0.8 <= 0.9 < sigma_1 ~ 1: wrinkled by this criterion
  const TensionField tf = run(s, sigma, {}, o);
  EXPECT_EQ(tf.tolerance, 0.9);
  EXPECT_EQ(tf.n_triangles, (std::array<int, 3>{0, n_tri(), 0}));
  EXPECT_STREQ(to_string(MembraneState::wrinkled), "wrinkled");
}

TEST(TensionField, InconsistentInputIsAnError) {
  const Shell& s = shell();
  const std::vector<Mat3d> sigma(s.mesh.tets.size(), Mat3d::Identity());
  const std::vector<Vec3d> u(s.mesh.nodes.size(), Vec3d::Zero());
  EXPECT_THROW(compute_tension_field(s.mesh.nodes, s.mesh.tets, s.outer, s.column, u,
                                     std::vector<Mat3d>(3), {}),
               Error);
  EXPECT_THROW(compute_tension_field(s.mesh.nodes, s.mesh.tets, s.outer, s.column, u, sigma,
                                     std::vector<double>(2, 1.0)),
               Error);
  EXPECT_THROW(
      compute_tension_field(s.mesh.nodes, s.mesh.tets, s.outer, std::vector<int>(2), u, sigma, {}),
      Error);
}

}  // namespace
}  // namespace plisse
