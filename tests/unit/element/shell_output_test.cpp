/// What the shell triangle reports through its thickness (docs/theory/shell.md, KL22-KL25)
/// against closed forms: a flat sheet in a homogeneous biaxial stretch (N = t λ3 σ, M = 0, the
/// same stress on both faces, thickness t/(λ1 λ2)) and a flat sheet bent onto a cylinder (M close
/// to D/R with D = μ t³/3, opposite stresses on the faces), with the rates of their errors.
#include "element/shell_output.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "shell_test_support.hpp"

namespace plisse::test {
namespace {

using namespace plisse::shell;

constexpr double kC1 = 0.5;  // [MPa]; μ = 2 c1 = 1 MPa

Vec3d flat(const Vec2d& p) { return Vec3d(p.x(), p.y(), 0.0); }

/// The largest entry of |A| (a scale for tolerances).
double largest(const Mat3d& A) { return A.cwiseAbs().maxCoeff(); }

/// The outputs of a flat sheet in x = Q diag(a, b, ·) Qᵀ X + c on the flat patch in the plane
/// with normal Q e3, against its plane-stress thickness stretch λ3 and principal Cauchy stresses
/// σ1, σ2: the same at every ζ, so N = t λ3 σ, M = 0, σ on both faces and the mid-surface,
/// thickness t λ3, the principal stretches (a, b, λ3) sorted at every face, J = a b λ3, and no
/// change of curvature; round-off only (the patch reproduces a homogeneous deformation exactly,
/// KL3).
void expect_homogeneous_stretch(double a, double b, double l3, const Vec2d& principal_stress,
                                double inverse_bulk_modulus) {
  const double t = 0.2;
  const Mat3d Q = Eigen::AngleAxisd(0.7, Vec3d(0.2, -1.0, 0.6).normalized()).toRotationMatrix();
  const Vec3d c(0.3, -0.2, 1.1);
  const Mat3d sigma =
      Q * Vec3d(principal_stress.x(), principal_stress.y(), 0.0).asDiagonal() * Q.transpose();
  const Mat3d N = t * l3 * sigma;
  std::vector<double> stretches = {a, b, l3};
  std::sort(stretches.rbegin(), stretches.rend());
  const NeoHookean nh{kC1};
  const ShellSection section = make_shell_section(t);
  for (unsigned seed : {1u, 2u}) {
    for (const SlotKinds& neighbours : {all_nodes(), free_sides({1, 2})}) {
      const auto p = plane_patch(1.0, 0.3, seed);
      const ShellGeometry g = compute_shell_geometry(
          map_patch(p, [&](const Vec2d& q) { return Vec3d(Q * flat(q)); }), neighbours);
      const PatchPositions x = map_patch(
          p, [&](const Vec2d& q) { return Vec3d(Q * Vec3d(a * q.x(), b * q.y(), 0.0) + c); });
      const PatchVec u = to_vector(x) - g.X;
      const ShellOutputs out = compute_shell_outputs(g, section, u, nh, inverse_bulk_modulus);
      const std::string what =
          "seed " + std::to_string(seed) + ", 1/kappa " + std::to_string(inverse_bulk_modulus);
      EXPECT_NEAR(out.thickness, t * l3, 1e-14) << what;
      EXPECT_LT(largest(out.membrane_force - N), 1e-13 * largest(N)) << what;
      EXPECT_LT(largest(out.bending_moment), 1e-13 * largest(N) * t) << what;
      EXPECT_LT(largest(out.curvature_change), 1e-12) << what;
      for (int f = 0; f < kShellFaces; ++f) {
        EXPECT_LT(largest(out.face_cauchy[f] - sigma), 1e-13 * largest(sigma)) << "face " << f;
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(out.face_stretches[f][k], stretches[k], 1e-13) << "face " << f;
      }
      const ElementFields fields = compute_shell_fields(g, section, u, nh, inverse_bulk_modulus);
      EXPECT_NEAR(fields.J, a * b * l3, 1e-14) << what;
      EXPECT_LT(largest(fields.cauchy - sigma), 1e-13 * largest(sigma)) << what;
    }
  }
}

TEST(ShellOutputs, HomogeneousBiaxialStretchOfAFlatSheet) {
  // Exactly incompressible neo-Hookean plane stress: λ3 = 1/(a b),
  // σ = diag(2 c1 (a² - λ3²), 2 c1 (b² - λ3²), 0).
  const double a = 1.3, b = 0.9, l3 = 1.0 / (a * b);
  expect_homogeneous_stretch(a, b, l3,
                             Vec2d(2 * kC1 * (a * a - l3 * l3), 2 * kC1 * (b * b - l3 * l3)), 0.0);
}

TEST(ShellOutputs, HomogeneousBiaxialStretchOfANearlyIncompressibleSheet) {
  // With a bulk modulus (KL12): λ3 the root of ∂W/∂λ3 = 0 by bisection and the principal Cauchy
  // stresses σ_α = λ_α ∂W/∂λ_α / J of the neo-Hookean energy written in principal stretches
  // (shell_test_support.hpp), at bulk moduli 10 and 0.8 MPa (ν near 0.45 and 0.06).
  const double a = 1.3, b = 0.9;
  for (double kappa : {10.0, 0.8}) {
    const PrincipalNeoHookean closed{kC1, kappa};
    const double l3 = closed.plane_stress_thickness(a, b);
    const Vec3d l(a, b, l3);
    const Vec2d stress(a * closed.derivative(l, 0) / l.prod(),
                       b * closed.derivative(l, 1) / l.prod());
    expect_homogeneous_stretch(a, b, l3, stress, 1.0 / kappa);
  }
}

/// The plane patch of size h wrapped without stretching onto the cylinder of radius R whose axis
/// lies in the plane at angle 0.3 to the x axis; the surface curves towards +z, the patch's
/// normal t3 (b > 0).
Vec3d on_cylinder(const Vec2d& p, double R) {
  const Vec2d axis(std::cos(0.3), std::sin(0.3));
  const Vec2d across(-axis.y(), axis.x());
  const double s = p.dot(across);
  return p.dot(axis) * flat(axis) + R * std::sin(s / R) * flat(across) +
         Vec3d(0, 0, R * (1.0 - std::cos(s / R)));
}

/// Relative errors of the outputs of a sheet of thickness t bent onto the cylinder of radius R.
struct BendingErrors {
  double moment;     ///< of M against -(D/R)(d ⊗ d + ½ a ⊗ a), D = μ t³/3
  double faces;      ///< of σ at the faces against ∓(μ t/R)(2 d ⊗ d + a ⊗ a)
  double opposite;   ///< |σ_top + σ_bottom| / |σ_top|
  double membrane;   ///< |N| / (t |σ_top|)
  double curvature;  ///< of the change of curvature against -(1/R) d0 ⊗ d0
  double thickness;  ///< |thickness / t - 1|
};

BendingErrors bending_errors(double t, double R, double h) {
  const double mu = 2.0 * kC1;
  const double D = mu * t * t * t / 3.0;
  const NeoHookean nh{kC1};
  const auto p = plane_patch(h, 0.0, 4);
  const ShellGeometry g = compute_shell_geometry(map_patch(p, flat), all_nodes());
  const PatchPositions x = map_patch(p, [&](const Vec2d& q) { return on_cylinder(q, R); });
  const ShellOutputs out =
      compute_shell_outputs(g, make_shell_section(t), to_vector(x) - g.X, nh, 0.0);
  // The current axes: a along the cylinder's axis, d across it in the triangle's current plane.
  const Vec3d a = flat(Vec2d(std::cos(0.3), std::sin(0.3)));
  const PatchVec xv = to_vector(x);
  const Vec3d t3 = triangle_normal(xv).normalized();
  const Vec3d d = t3.cross(a).normalized();
  const Vec3d d0 = flat(Vec2d(-std::sin(0.3), std::cos(0.3)));
  const Mat3d M = -(D / R) * (d * d.transpose() + 0.5 * a * a.transpose());
  const Mat3d top = -(mu * t / R) * (2.0 * d * d.transpose() + a * a.transpose());
  const Mat3d kappa = -(1.0 / R) * d0 * d0.transpose();
  BendingErrors e{};
  e.moment = largest(out.bending_moment - M) / largest(M);
  e.faces = std::max(largest(out.face_cauchy[kTopFace] - top),
                     largest(out.face_cauchy[kBottomFace] + top)) /
            largest(top);
  e.opposite = largest(out.face_cauchy[kTopFace] + out.face_cauchy[kBottomFace]) /
               largest(out.face_cauchy[kTopFace]);
  e.membrane = largest(out.membrane_force) / (t * largest(out.face_cauchy[kTopFace]));
  e.curvature = largest(out.curvature_change - kappa) / largest(kappa);
  e.thickness = std::abs(out.thickness / t - 1.0);
  return e;
}

TEST(ShellOutputs, SheetBentOntoACylinder) {
  // Bent towards t3, κ = B - b = -(1/R) d0 ⊗ d0: the top face is compressed, the bottom
  // stretched, and small-strain incompressible plane stress gives M = (μ t³/6)(κ + tr κ I),
  // i.e. -(D/R)(d ⊗ d + ½ a ⊗ a), D = μ t³/3 (KL23). Two errors remain: the curvature of the
  // discrete patch and its membrane strain, O((h/R)²), and the finite strain through the
  // thickness: the faces are stretched by ∓t/(2R), so σ_top + σ_bottom and N are O(t/R) of the
  // face stress (the stress is not odd in the strain) and M is O((t/R)²) off D/R (its lever arm
  // cancels the even part). At h = R/400, t/R = 1/10, 1/20, 1/40, measured (relative):
  //   M: 9.5e-3, 2.4e-3, 5.9e-4 (order 2.0); the faces' σ: 6.2e-2, 3.0e-2, 1.4e-2 (order 1.0);
  //   σ_top + σ_bottom: 1.1e-1, 5.5e-2, 2.8e-2 of σ_top (order 1.0); |N| / (t |σ_top|): 3.4e-2,
  //   1.7e-2, 8.8e-3 (order 1.0); the change of curvature 1.2e-6 and the thickness 4.7e-7, both
  //   the patch's O((h/R)²) (falling fourfold with each halving of h).
  const double R = 1.0;
  const double h = R / 400;
  std::vector<double> moment, faces, opposite, membrane;
  for (const double t : {R / 10, R / 20, R / 40}) {
    const BendingErrors e = bending_errors(t, R, h);
    moment.push_back(e.moment);
    faces.push_back(e.faces);
    opposite.push_back(e.opposite);
    membrane.push_back(e.membrane);
    EXPECT_LT(e.curvature, 1e-5) << "t/R = " << t / R;
    EXPECT_LT(e.thickness, 1e-6) << "t/R = " << t / R;
  }
  EXPECT_LT(moment.back(), 8e-4);
  EXPECT_GT(observed_order(moment), 1.9);
  EXPECT_LT(faces.back(), 2e-2);
  EXPECT_GT(observed_order(faces), 0.9);
  EXPECT_LT(opposite.back(), 4e-2);
  EXPECT_GT(observed_order(opposite), 0.9);
  EXPECT_GT(observed_order(membrane), 0.9);
}

}  // namespace
}  // namespace plisse::test
