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

namespace plisse {
namespace {

// The tension field of a shell (element: shell; wrinkles.md, T1s): each mid-surface triangle is
// its own column. A flat sheet (20 x 10 mm, triangles of 1 mm), turned out of the coordinate
// planes by Q, in a homogeneous in-plane stretch (λ1, λ2) along axes turned by β in its plane:
// incompressible plane stress of a neo-Hookean membrane, σ_α = 2 c1 (λ_α² − λ3²),
// λ3 = 1/(λ1 λ2) (docs/theory/shell.md, section 9: the closed form the shell element meets to
// round-off). Uniaxial tension with the lateral contraction free, λ2 = λ3 = λ1^(-1/2), has σ2 = 0
// exactly: wrinkled.
struct FlatState {
  double lambda1, lambda2;
  MembraneState state;
};

TEST(ShellTensionField, HomogeneousStatesOfATiltedSheetAreClassifiedFromTheirPrincipalStresses) {
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 20.0;
  spec.width = 10.0;
  spec.thickness = 0.5;
  spec.element_size = 1.0;
  Mesh mesh = generate_shell_surface(spec);
  ASSERT_TRUE(mesh.is_shell());
  const Mat3d Q = (Eigen::AngleAxisd(0.4, Vec3d(1.0, 2.0, 0.5).normalized())).toRotationMatrix();
  for (Vec3d& X : mesh.nodes) X = Q * X;
  const double c1 = 0.2, beta = 0.3;
  // The in-plane axes of the stretch: e1, e2 turned by β about the sheet's normal Q e_z.
  const Vec3d a1 = Q * Vec3d(std::cos(beta), std::sin(beta), 0.0);
  const Vec3d a2 = Q * Vec3d(-std::sin(beta), std::cos(beta), 0.0);
  const Vec3d a3 = Q * Vec3d::UnitZ();
  const std::vector<int> all = mesh.surface_tags.at("top");
  ASSERT_EQ(all.size(), mesh.triangles.size());
  for (const FlatState& f :
       {FlatState{1.2, 1.1, MembraneState::taut},
        FlatState{1.3, 1.0 / std::sqrt(1.3), MembraneState::wrinkled},
        FlatState{1.3, 0.8, MembraneState::wrinkled}, FlatState{0.9, 0.95, MembraneState::slack}}) {
    SCOPED_TRACE("λ1 = " + std::to_string(f.lambda1) + ", λ2 = " + std::to_string(f.lambda2));
    const double lambda3 = 1.0 / (f.lambda1 * f.lambda2);
    const double s1 = 2 * c1 * (f.lambda1 * f.lambda1 - lambda3 * lambda3);
    const double s2 = 2 * c1 * (f.lambda2 * f.lambda2 - lambda3 * lambda3);
    const Mat3d F = f.lambda1 * a1 * a1.transpose() + f.lambda2 * a2 * a2.transpose() +
                    lambda3 * a3 * a3.transpose();
    const Mat3d sigma = s1 * a1 * a1.transpose() + s2 * a2 * a2.transpose();
    std::vector<Vec3d> u;
    for (const Vec3d& X : mesh.nodes) u.push_back((F - Mat3d::Identity()) * X);
    const std::vector<Mat3d> stress(mesh.triangles.size(), sigma);
    const TensionField tf = compute_shell_tension_field(mesh.nodes, mesh.triangles, all, u, stress);
    ASSERT_EQ(tf.element_state.size(), mesh.triangles.size());
    ASSERT_EQ(tf.triangle_state.size(), all.size());
    const double larger = std::max(s1, s2), smaller = std::min(s1, s2);
    EXPECT_NEAR(tf.tolerance, 1e-6 * std::abs(larger), 1e-15);
    for (std::size_t e = 0; e < all.size(); ++e) {
      EXPECT_EQ(tf.element_state[e], f.state) << "triangle " << e;
      EXPECT_EQ(tf.triangle_state[e], f.state) << "triangle " << e;
      EXPECT_NEAR(tf.principal_stress[e][0], larger, 1e-13 * std::abs(larger));
      EXPECT_NEAR(tf.principal_stress[e][1], smaller, 1e-13 * std::abs(larger));
    }
    EXPECT_EQ(tf.n_elements[static_cast<int>(f.state)], static_cast<int>(mesh.triangles.size()));
    EXPECT_EQ(tf.n_triangles[static_cast<int>(f.state)], static_cast<int>(all.size()));
    // The same through the mesh overload, which takes the shell path for a shell mesh.
    const TensionField again = compute_tension_field(mesh, u, stress, {}, {}, "bottom");
    EXPECT_EQ(again.element_state, tf.element_state);
  }
}

TEST(ShellTensionField, EachTriangleIsItsOwnColumnAndTheSurfaceListsItsOwn) {
  // The left half of the sheet in biaxial tension, the right half compressed: the counts split
  // exactly by the triangles' centroids, and a surface of some triangles reports those.
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 20.0;
  spec.width = 10.0;
  spec.thickness = 0.5;
  spec.element_size = 2.0;
  const Mesh mesh = generate_shell_surface(spec);
  std::vector<Mat3d> stress;
  int left = 0;
  std::vector<int> surface;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const auto& t = mesh.triangles[e];
    const double x = (mesh.nodes[t[0]].x() + mesh.nodes[t[1]].x() + mesh.nodes[t[2]].x()) / 3.0;
    const bool tension = x < 10.0;
    left += tension;
    stress.push_back(tension ? Mat3d(Vec3d(1.0, 0.5, 0.0).asDiagonal())
                             : Mat3d(Vec3d(-1.0, -0.5, 0.0).asDiagonal()));
    if (e % 3 == 0) surface.push_back(static_cast<int>(e));
  }
  const std::vector<Vec3d> u(mesh.nodes.size(), Vec3d::Zero());
  const TensionField tf =
      compute_shell_tension_field(mesh.nodes, mesh.triangles, surface, u, stress);
  EXPECT_EQ(tf.n_elements[0], left);
  EXPECT_EQ(tf.n_elements[2], static_cast<int>(mesh.triangles.size()) - left);
  ASSERT_EQ(tf.triangle_state.size(), surface.size());
  for (std::size_t k = 0; k < surface.size(); ++k)
    EXPECT_EQ(tf.triangle_state[k], tf.element_state[static_cast<std::size_t>(surface[k])]);
  EXPECT_THROW(compute_shell_tension_field(mesh.nodes, mesh.triangles, {-1}, u, stress), Error);
  EXPECT_THROW(compute_shell_tension_field(mesh.nodes, mesh.triangles, surface, u, {}), Error);
}

}  // namespace
}  // namespace plisse
