// The Taylor-Hood (P2/P1) element kernel on straight and curved 10-node tetrahedra: shape
// functions, geometry, residual = gradient of the mixed functional and tangent = derivative of the
// residual (finite differences, observed order 2) for every material model, exact and near
// incompressibility; symmetry, rigid motions, homogeneous states to round-off, closed-form
// stresses, failure reporting.
#include "element/taylor_hood.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>

#include "element_test_support.hpp"
#include "material/neo_hookean.hpp"
#include "material/registry.hpp"

namespace plisse::taylor_hood {
namespace {

constexpr double kC1 = 0.5;  // [MPa]

/// The 10 nodes of the tetrahedron with corners X: edge nodes at the midpoints, moved by up to
/// `bulge` × (its smallest height) in a fixed pseudo-random direction each (0: a straight element).
std::array<Vec3d, kNodes> ten_nodes(const std::array<Vec3d, 4>& X, double bulge,
                                    unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::array<Vec3d, kNodes> nodes;
  const double volume = (X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) / 6.0;
  double largest_face = 0.0;
  for (int a = 0; a < 4; ++a) {
    nodes[a] = X[a];
    const Vec3d &p = X[(a + 1) % 4], &q = X[(a + 2) % 4], &r = X[(a + 3) % 4];
    largest_face = std::max(largest_face, 0.5 * (q - p).cross(r - p).norm());
  }
  const double height = 3.0 * std::abs(volume) / largest_face;
  for (int k = 0; k < 6; ++k) {
    const Vec3d direction(unit(rng), unit(rng), unit(rng));
    nodes[4 + k] = 0.5 * (X[kTetEdges[k][0]] + X[kTetEdges[k][1]]) + bulge * height * direction;
  }
  return nodes;
}

/// x_e of the homogeneous deformation x = F0 X + c (pressures `p`).
ElemVec homogeneous_state(const std::array<Vec3d, kNodes>& X, const Mat3d& F0, double p = 0.0,
                          const Vec3d& c = Vec3d::Zero()) {
  ElemVec x;
  for (int a = 0; a < kNodes; ++a) x.segment<3>(dof_u(a, 0)) = (F0 - Mat3d::Identity()) * X[a] + c;
  x.tail<kDofP>().setConstant(p);
  return x;
}

ElemVec random_state(unsigned seed, double size, double u_fraction) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  ElemVec x;
  for (int i = 0; i < kDofU; ++i) x(i) = u_fraction * size * unit(rng);
  for (int a = 0; a < kDofP; ++a) x(dof_p(a)) = kC1 * unit(rng);
  return x;
}

TEST(TaylorHoodShape, PartitionOfUnityAndKroneckerProperty) {
  const std::array<std::array<double, 4>, kNodes> node_L = {{{1, 0, 0, 0},
                                                             {0, 1, 0, 0},
                                                             {0, 0, 1, 0},
                                                             {0, 0, 0, 1},
                                                             {.5, .5, 0, 0},
                                                             {0, .5, .5, 0},
                                                             {.5, 0, .5, 0},
                                                             {.5, 0, 0, .5},
                                                             {0, 0, .5, .5},
                                                             {0, .5, 0, .5}}};
  for (int b = 0; b < kNodes; ++b) {
    const auto N = shape_values(node_L[b]);
    for (int a = 0; a < kNodes; ++a) EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-15);
  }
  for (int q = 0; q < kQuadPoints; ++q) {
    const auto N = shape_values(kQuadrature.points[q]);
    double sum = 0.0;
    for (double n : N) sum += n;
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_LT(reference_derivatives()[q].rowwise().sum().norm(), 1e-14);
  }
}

TEST(TaylorHoodShape, DerivativesAreThoseOfTheValues) {
  const std::array<double, 4> L = {0.1, 0.2, 0.3, 0.4};
  const NodeGradients dN = shape_derivatives(L);
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k) {
    std::array<double, 4> plus = L, minus = L;
    plus[k + 1] += h;
    plus[0] -= h;
    minus[k + 1] -= h;
    minus[0] += h;
    const auto Np = shape_values(plus), Nm = shape_values(minus);
    for (int a = 0; a < kNodes; ++a) EXPECT_NEAR(dN(k, a), (Np[a] - Nm[a]) / (2 * h), 1e-9);
  }
}

TEST(TaylorHoodGeometry, StraightElementHasTheLinearVolumeAndCurvedOneTheIntegral) {
  const auto X = test::random_tet(3);
  const double linear_volume = (X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) / 6.0;
  const Geometry straight = compute_geometry(ten_nodes(X, 0.0));
  EXPECT_NEAR(straight.volume, linear_volume, 1e-13 * linear_volume);
  // On a curved element ∫ F dV at the identity state is V I (the identity integrates exactly).
  const Geometry curved = compute_geometry(ten_nodes(X, 0.1));
  const Mat3d integral = deformation_integral(curved, ElemVec::Zero());
  EXPECT_LT((integral - curved.volume * Mat3d::Identity()).norm(), 1e-13 * curved.volume);
  EXPECT_GT(std::abs(curved.volume - linear_volume), 1e-4 * linear_volume);
}

TEST(TaylorHoodGeometry, InvertedOrFoldedElementIsRefused) {
  auto X = test::random_tet(4);
  std::swap(X[2], X[3]);
  EXPECT_THROW(compute_geometry(ten_nodes(X, 0.0)), Error);
  auto nodes = ten_nodes(test::random_tet(4), 0.0);
  nodes[4] = nodes[1] + 0.2 * (nodes[1] - nodes[0]);  // edge node beyond its corner: folded
  EXPECT_THROW(compute_geometry(nodes), Error);
}

/// ‖D (K_fd - K) D‖ / ‖D K D‖ with central differences of the residual (steps h D e_j).
template <class Material>
double tangent_error(const Geometry& g, const ElemVec& x, const ElemMat& K, const Material& mat,
                     double inverse_bulk_modulus, double h) {
  ElemVec scale;
  scale.head<kDofU>().setConstant(g.size);
  scale.tail<kDofP>().setConstant(kC1);
  ElemMat K_fd;
  for (int j = 0; j < kDof; ++j) {
    ElemVec plus = x, minus = x, r_plus, r_minus;
    plus(j) += h * scale(j);
    minus(j) -= h * scale(j);
    EXPECT_TRUE(assemble(g, plus, mat, inverse_bulk_modulus, r_plus, nullptr).ok);
    EXPECT_TRUE(assemble(g, minus, mat, inverse_bulk_modulus, r_minus, nullptr).ok);
    K_fd.col(j) = (r_plus - r_minus) / (2.0 * h * scale(j));
  }
  const auto D = scale.asDiagonal();
  return (D * (K_fd - K) * D).norm() / (D * K * D).norm();
}

/// Residual against central differences of the functional Π_e (relative, scaled as above).
template <class Material>
double residual_error(const Geometry& g, const ElemVec& x, const ElemVec& r, const Material& mat,
                      double inverse_bulk_modulus, double h) {
  ElemVec r_fd;
  for (int j = 0; j < kDof; ++j) {
    const double step = h * (j < kDofU ? g.size : kC1);
    ElemVec plus = x, minus = x;
    plus(j) += step;
    minus(j) -= step;
    r_fd(j) = (compute_element_energy(g, plus, mat, inverse_bulk_modulus) -
               compute_element_energy(g, minus, mat, inverse_bulk_modulus)) /
              (2.0 * step);
  }
  return (r_fd - r).norm() / r.norm();
}

TEST(TaylorHoodElement, ResidualIsGradientOfFunctionalAndTangentItsDerivativeForEveryMaterial) {
  for (const AnyMaterial& any : test::every_material())
    for (const double inverse_bulk_modulus : {0.0, 0.1})
      for (const double bulge : {0.0, 0.1})
        std::visit(
            [&](const auto& mat) {
              for (unsigned seed = 1; seed <= 2; ++seed) {
                const std::array<Vec3d, kNodes> nodes =
                    ten_nodes(test::random_tet(seed), bulge, seed);
                const Geometry g = compute_geometry(nodes);
                ElemVec x, r;
                ElemMat K;
                ElementStatus status;
                for (unsigned attempt = 0;; ++attempt) {
                  constexpr bool fibres = requires { std::decay_t<decltype(mat)>::kIsotropic; };
                  x = random_state(seed + 100 * attempt, g.size, fibres ? 0.01 : 0.08);
                  if constexpr (fibres) {
                    // Fibres: ψ'' jumps at Ī4 = 1 (material/fibre_reinforced.hpp), which the
                    // differences must not straddle: stretched 1.3-fold in x and y, with a
                    // smaller random part, the family in the x-y plane is well in extension and
                    // the one along z well in compression at every point of the curved elements.
                    const Mat3d F0 = Vec3d(1.3, 1.3, 1 / 1.69).asDiagonal();
                    x.head<kDofU>() += homogeneous_state(nodes, F0).head<kDofU>();
                  }
                  status = assemble(g, x, mat, inverse_bulk_modulus, r, &K);
                  if (status.ok && status.min_J > 0.5) break;
                }
                // Central differences: the error falls as h² (observed order 2) down to
                // round-off; at h = 1e-6 the truncation error measured here is below 2e-8.
                std::vector<double> residual_errors, tangent_errors;
                for (double h : {4e-3, 2e-3, 1e-3}) {
                  residual_errors.push_back(residual_error(g, x, r, mat, inverse_bulk_modulus, h));
                  tangent_errors.push_back(tangent_error(g, x, K, mat, inverse_bulk_modulus, h));
                }
                EXPECT_NEAR(test::observed_order(residual_errors), 2.0, 0.25);
                EXPECT_NEAR(test::observed_order(tangent_errors), 2.0, 0.25);
                EXPECT_LT(residual_error(g, x, r, mat, inverse_bulk_modulus, 1e-6), 1e-7);
                EXPECT_LT(tangent_error(g, x, K, mat, inverse_bulk_modulus, 1e-6), 1e-7);
                EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
              }
            },
            any);
}

TEST(TaylorHoodElement, RigidMotionWithZeroPressureGivesZeroResidual) {
  const Geometry g = compute_geometry(ten_nodes(test::random_tet(5), 0.1));
  const auto X = ten_nodes(test::random_tet(5), 0.1);
  const NeoHookean mat{kC1};
  const ElemVec x = homogeneous_state(X, test::rotation(Vec3d(1, 2, 3), 0.7), 0.0, Vec3d(1, -2, 3));
  ElemVec r;
  ASSERT_TRUE(assemble(g, x, mat, 0.0, r, nullptr).ok);
  EXPECT_LT(r.norm(), 1e-13 * kC1 * g.size * g.size);
}

TEST(TaylorHoodElement, UniaxialIncompressibleStretchGivesClosedFormCauchyStress) {
  // F = diag(λ, λ^-1/2, λ^-1/2): neo-Hookean σ_xx = 2 c1 (λ² - 1/λ), lateral stress free with
  // p = 2 c1 (1/λ - tr B / 3), the same closed form as the MINI test; on a curved element too.
  const NeoHookean mat{kC1};
  const auto X = ten_nodes(test::random_tet(8), 0.1);
  const Geometry g = compute_geometry(X);
  for (double lambda : {0.7, 1.0, 1.5, 2.5}) {
    const double lateral = 1.0 / std::sqrt(lambda);
    const double trace_B = lambda * lambda + 2.0 / lambda;
    const double p = 2 * kC1 * (1.0 / lambda - trace_B / 3.0);
    const ElemVec x = homogeneous_state(X, Vec3d(lambda, lateral, lateral).asDiagonal(), p);
    ElemVec r;
    ASSERT_TRUE(assemble(g, x, mat, 0.0, r, nullptr).ok);
    const ElementFields f = compute_element_fields(g, x, mat);
    const double sigma_xx = 2 * kC1 * (lambda * lambda - 1.0 / lambda);
    const double tolerance = 1e-13 * 2 * kC1 * trace_B;
    EXPECT_NEAR(f.cauchy(0, 0), sigma_xx, tolerance) << "λ = " << lambda;
    EXPECT_NEAR(f.cauchy(1, 1), 0.0, tolerance);
    EXPECT_NEAR(f.cauchy(2, 2), 0.0, tolerance);
    EXPECT_NEAR(f.J, 1.0, 1e-14);
    EXPECT_NEAR(f.pressure, p, 1e-14);
    EXPECT_LT(r.tail<kDofP>().norm(), 1e-14 * g.volume);
    // Uniform stress: the nodal forces are those of the boundary traction, and they balance.
    Vec3d total = Vec3d::Zero();
    for (int a = 0; a < kNodes; ++a) total += r.segment<3>(dof_u(a, 0));
    EXPECT_LT(total.norm(), 1e-13 * std::abs(sigma_xx) * g.size * g.size + 1e-300);
  }
}

TEST(TaylorHoodElement, InvertedStateIsReportedNotThrown) {
  const auto X = ten_nodes(test::random_tet(9), 0.0);
  const Geometry g = compute_geometry(X);
  const ElemVec x = homogeneous_state(X, Vec3d(-1.0, 1.0, 1.0).asDiagonal());
  ElemVec r;
  ElemMat K;
  const ElementStatus s = assemble(g, x, NeoHookean{kC1}, 0.0, r, &K);
  EXPECT_FALSE(s.ok);
  EXPECT_LT(s.min_J, 0.0);
  EXPECT_EQ(r.norm(), 0.0);
  EXPECT_EQ(K.norm(), 0.0);
}

TEST(TaylorHoodElement, StrainEnergyOfHomogeneousStretchIsWTimesVolume) {
  const NeoHookean mat{kC1};
  const auto X = ten_nodes(test::random_tet(10), 0.1);
  const Geometry g = compute_geometry(X);
  const double lambda = 1.3, lateral = 1.0 / std::sqrt(lambda);
  const ElemVec x = homogeneous_state(X, Vec3d(lambda, lateral, lateral).asDiagonal(), 0.2);
  const double W = kC1 * (lambda * lambda + 2.0 / lambda - 3.0);
  EXPECT_NEAR(compute_strain_energy(g, x, mat, 0.0), W * g.volume, 1e-13 * W * g.volume);
  EXPECT_NEAR(compute_strain_energy(g, x, mat, 0.5), (W + 0.25 * 0.2 * 0.2) * g.volume,
              1e-13 * W * g.volume);
}

}  // namespace
}  // namespace plisse::taylor_hood
