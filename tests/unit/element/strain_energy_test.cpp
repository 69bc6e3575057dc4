// Strain energy of the MINI element (element/strain_energy.hpp, SE1-SE2): closed forms W(λ) x V
// for every registered model under homogeneous deformation, the volumetric part p²/(2κ), and the
// derivative along a displacement path equal to the internal force work (finite differences
// against the condensed residual of element/mini.hpp).
#include "element/strain_energy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>

#include "element/mini.hpp"
#include "element_test_support.hpp"
#include "material/registry.hpp"

namespace plisse {
namespace {

using mini::BubbleVec;
using mini::ElemMat;
using mini::ElemVec;
using mini::TetGeometry;

/// A registered model with parameters and its energy written out here in the invariants (or the
/// stretches), independent of the model code (the formulas of each model's header).
struct ModelCase {
  MaterialValues values;
  std::function<double(double I1bar, double I2bar)> W;
  /// For a model not of the invariants alone (fibres): W of the principal stretches of
  /// F = Q diag(λ), the fibre directions given along the axes of diag(λ).
  std::function<double(const Vec3d& lambda)> W_of_stretches = {};
};

const std::map<std::string, ModelCase>& model_cases() {
  static const std::map<std::string, ModelCase> cases = {
      {"neo-hookean", {{{"c1", 0.2}}, [](double I1, double) { return 0.2 * (I1 - 3.0); }}},
      {"mooney-rivlin",
       {{{"c1", 0.15}, {"c2", 0.05}},
        [](double I1, double I2) { return 0.15 * (I1 - 3.0) + 0.05 * (I2 - 3.0); }}},
      {"fung",
       {{{"mu", 0.4}, {"gamma", 1.5}},
        [](double I1, double) { return 0.4 / (2.0 * 1.5) * std::expm1(1.5 * (I1 - 3.0)); }}},
      {"yeoh",
       {{{"c1", 0.2}, {"c2", -0.02}, {"c3", 0.01}},
        [](double I1, double) {
          const double x = I1 - 3.0;
          return 0.2 * x - 0.02 * x * x + 0.01 * x * x * x;
        }}},
      {"gent",
       {{{"mu", 0.4}, {"jm", 5.0}},
        [](double I1, double) { return -0.4 * 5.0 / 2.0 * std::log1p(-(I1 - 3.0) / 5.0); }}},
      {"arruda-boyce",
       {{{"mu", 0.35}, {"lambda_m", 3.0}},
        [](double I1, double) {
          const double alpha[] = {0.5, 1.0 / 20.0, 11.0 / 1050.0, 19.0 / 7000.0, 519.0 / 673750.0};
          double W = 0.0;
          for (int i = 1; i <= 5; ++i)
            W += 0.35 * alpha[i - 1] / std::pow(3.0, 2 * i - 2) *
                 (std::pow(I1, i) - std::pow(3.0, i));
          return W;
        }}},
      // Ogden with α = 2 and -2 is Mooney-Rivlin, c1 = μ1/2, c2 = -μ2/2 (Σ λ̄⁻² = Ī2): its energy
      // through the principal stretches against the invariants.
      {"ogden",
       {{{"mu1", 0.3}, {"alpha1", 2.0}, {"mu2", -0.1}, {"alpha2", -2.0}},
        [](double I1, double I2) { return 0.15 * (I1 - 3.0) + 0.05 * (I2 - 3.0); }}},
      // Fibres along x and z of the reference: Ī4 = J^(-2/3) λx² and J^(-2/3) λz², each active
      // above 1 with ψ = k1/(2 k2) (exp(k2 (Ī4 - 1)²) - 1).
      {"fibre-reinforced",
       {{{"c1", 0.2}, {"k1", 0.8}, {"k2", 0.5}, {"a1_x", 1.0}, {"a2_z", 1.0}},
        [](double, double) { return 0.0; },
        [](const Vec3d& l) {
          const double b = std::pow(l.prod(), -2.0 / 3.0);
          double W = 0.2 * (b * l.squaredNorm() - 3.0);
          for (const double stretch : {l(0), l(2)}) {
            const double x = b * stretch * stretch - 1.0;
            if (x > 0.0) W += 0.8 / (2.0 * 0.5) * std::expm1(0.5 * x * x);
          }
          return W;
        }}},
  };
  return cases;
}

TEST(StrainEnergy, EveryRegisteredModelHasAClosedFormCaseHere) {
  for (const MaterialModelInfo& info : material_models())
    EXPECT_EQ(model_cases().count(info.name), 1u) << "no strain energy test for " << info.name;
}

const auto kX = test::random_tet(3);

/// (Ī1, Ī2) of F = diag(λ1, λ2, λ3).
std::pair<double, double> isochoric_invariants(const Vec3d& lambda) {
  const double J = lambda.prod();
  const Vec3d sq = lambda.cwiseProduct(lambda);
  const double I1 = sq.sum();
  const double I2 = sq(0) * sq(1) + sq(1) * sq(2) + sq(2) * sq(0);
  return {std::pow(J, -2.0 / 3.0) * I1, std::pow(J, -4.0 / 3.0) * I2};
}

TEST(StrainEnergy, HomogeneousDeformationGivesWTimesVolumeForEveryModel) {
  const TetGeometry g = mini::compute_tet_geometry(kX);
  const Mat3d Q = test::rotation(Vec3d(1, 2, -1), 0.7);  // frame-indifference comes for free
  for (const auto& [name, model] : model_cases()) {
    const AnyMaterial material = make_material(name, model.values);
    // Incompressible uniaxial stretch/compression, then a volume-changing stretch (the energy uses
    // the isochoric invariants, so J != 1 must not enter W).
    for (const Vec3d& lambda :
         {Vec3d(1.3, 1.0 / std::sqrt(1.3), 1.0 / std::sqrt(1.3)),
          Vec3d(0.8, 1.0 / std::sqrt(0.8), 1.0 / std::sqrt(0.8)), Vec3d(1.2, 0.9, 1.1)}) {
      const Mat3d F = Q * lambda.asDiagonal();
      ElemVec x = test::homogeneous_state(kX, F, Vec3d(0.1, -0.2, 0.3));
      const double p0 = 0.05;  // [MPa], same at every node
      for (int a = 0; a < 4; ++a) x(mini::dof_p(a)) = p0;
      const auto [I1bar, I2bar] = isochoric_invariants(lambda);
      const double W = model.W_of_stretches ? model.W_of_stretches(lambda) : model.W(I1bar, I2bar);
      EXPECT_GT(W, 0.0) << name;
      // Exact incompressibility: no volumetric part.
      const mini::StrainEnergy exact =
          mini::compute_strain_energy(g, x, material, 0.0, BubbleVec::Zero());
      EXPECT_NEAR(exact.isochoric, W * g.volume, 1e-12 * W * g.volume) << name;
      EXPECT_EQ(exact.volumetric, 0.0) << name;
      // Nearly incompressible, κ = 50 MPa: p0² V / (2κ) added.
      const double kappa = 50.0;
      const mini::StrainEnergy nearly =
          mini::compute_strain_energy(g, x, material, 1.0 / kappa, BubbleVec::Zero());
      EXPECT_NEAR(nearly.isochoric, exact.isochoric, 0.0) << name;
      EXPECT_NEAR(nearly.volumetric, p0 * p0 / (2.0 * kappa) * g.volume, 1e-15) << name;
      EXPECT_NEAR(nearly.total(), nearly.isochoric + nearly.volumetric, 0.0);
    }
  }
}

TEST(StrainEnergy, HomogeneousStateKeepsTheBubbleAtZero) {
  // The state used above is the element's own solution: the bubble solve returns b = 0, so the
  // closed form is the energy at the converged state, not just at b = 0.
  const TetGeometry g = mini::compute_tet_geometry(kX);
  const AnyMaterial material =
      make_material("mooney-rivlin", model_cases().at("mooney-rivlin").values);
  const ElemVec x = test::homogeneous_state(kX, Vec3d(1.3, 0.9, 0.85).asDiagonal());
  BubbleVec b = BubbleVec::Zero();
  ElemVec r;
  const auto status = std::visit(
      [&](const auto& m) { return mini::assemble_mini(g, x, m, 0.0, b, r, nullptr); }, material);
  ASSERT_TRUE(status.ok);
  EXPECT_LT(b.norm(), 1e-12 * g.size);
}

TEST(StrainEnergy, ZeroInTheReferenceStateForEveryModel) {
  const TetGeometry g = mini::compute_tet_geometry(kX);
  for (const auto& [name, model] : model_cases()) {
    const auto e = mini::compute_strain_energy(
        g, ElemVec::Zero(), make_material(name, model.values), 0.02, BubbleVec::Zero());
    EXPECT_NEAR(e.total(), 0.0, 1e-15) << name;
  }
}

/// Element solution at x: bubble solved (warm start `b`), condensed residual and tangent.
void solve_element(const TetGeometry& g, const ElemVec& x, const AnyMaterial& material,
                   double inverse_bulk_modulus, BubbleVec& b, ElemVec& r, ElemMat& K) {
  const auto status = std::visit(
      [&](const auto& m) { return mini::assemble_mini(g, x, m, inverse_bulk_modulus, b, r, &K); },
      material);
  ASSERT_TRUE(status.ok);
}

/// E at x with the bubble solved there.
double energy_at(const TetGeometry& g, const ElemVec& x, const AnyMaterial& material,
                 double inverse_bulk_modulus, BubbleVec b) {
  ElemVec r;
  ElemMat K;
  solve_element(g, x, material, inverse_bulk_modulus, b, r, K);
  return mini::compute_strain_energy(g, x, material, inverse_bulk_modulus, b).total();
}

TEST(StrainEnergy, RateAlongADisplacementPathIsTheInternalForceWork) {
  // At fixed pressures, E = Π - p · r_p (SE2), so dE/ds = r_u · du - p · (dr_p/du) du, with the
  // bubble re-solved at every point of the path; dr_p/du is the condensed tangent block.
  const TetGeometry g = mini::compute_tet_geometry(kX);
  for (const auto& [name, model] : model_cases()) {
    const AnyMaterial material = make_material(name, model.values);
    for (double inverse_bulk_modulus : {0.0, 1.0 / 20.0}) {
      ElemVec x = test::random_state(11, g, 0.08, 0.1);
      ElemVec du = test::random_state(12, g, 1.0, 0.0);
      BubbleVec b = BubbleVec::Zero();
      ElemVec r;
      ElemMat K;
      solve_element(g, x, material, inverse_bulk_modulus, b, r, K);
      const Eigen::Vector4d p = x.tail<4>();
      const double work = r.head<12>().dot(du.head<12>());
      const double pressure_part = p.dot(K.bottomLeftCorner<4, 12>() * du.head<12>());
      const double h = 1e-6;
      const double rate = (energy_at(g, x + h * du, material, inverse_bulk_modulus, b) -
                           energy_at(g, x - h * du, material, inverse_bulk_modulus, b)) /
                          (2.0 * h);
      const double expected = work - pressure_part;
      EXPECT_NEAR(rate, expected, 1e-6 * (std::abs(work) + std::abs(pressure_part)))
          << name << ", 1/kappa = " << inverse_bulk_modulus;
    }
  }
}

/// Nodal pressures solving the element's own pressure equations r_p(x) = 0 at the displacements
/// of x (Newton on the condensed p-p block; r_p is affine in p up to the bubble's response).
void solve_pressures(const TetGeometry& g, ElemVec& x, const AnyMaterial& material,
                     double inverse_bulk_modulus, BubbleVec& b) {
  for (int it = 0; it < 20; ++it) {
    ElemVec r;
    ElemMat K;
    solve_element(g, x, material, inverse_bulk_modulus, b, r, K);
    if (r.tail<4>().norm() < 1e-15 * g.volume) return;
    x.tail<4>() -= K.bottomRightCorner<4, 4>().lu().solve(r.tail<4>());
  }
  FAIL() << "pressure equations not solved";
}

TEST(StrainEnergy, NearlyIncompressibleRateWithPressureEquationsSolvedIsTheDisplacementWork) {
  // The literal check of SE2: along u(s), with p(s) and b(s) solving their element equations,
  // dE/ds = r_u · du (no pressure term).
  const TetGeometry g = mini::compute_tet_geometry(kX);
  const double inverse_bulk_modulus = 1.0 / 10.0;  // κ = 10 MPa: J - 1 visible
  for (const auto& [name, model] : model_cases()) {
    const AnyMaterial material = make_material(name, model.values);
    ElemVec x = test::random_state(21, g, 0.08, 0.0);
    const ElemVec du = test::random_state(22, g, 1.0, 0.0);
    BubbleVec b = BubbleVec::Zero();
    solve_pressures(g, x, material, inverse_bulk_modulus, b);
    ElemVec r;
    ElemMat K;
    solve_element(g, x, material, inverse_bulk_modulus, b, r, K);
    const double work = r.head<12>().dot(du.head<12>());
    const double h = 1e-6;
    const auto energy_on_path = [&](double s) {
      ElemVec xs = x + s * du;
      BubbleVec bs = b;
      solve_pressures(g, xs, material, inverse_bulk_modulus, bs);
      return mini::compute_strain_energy(g, xs, material, inverse_bulk_modulus, bs).total();
    };
    const double rate = (energy_on_path(h) - energy_on_path(-h)) / (2.0 * h);
    EXPECT_GT(mini::compute_strain_energy(g, x, material, inverse_bulk_modulus, b).volumetric, 0.0);
    EXPECT_NEAR(rate, work, 1e-6 * std::abs(work)) << name;
  }
}

TEST(StrainEnergy, VariantOverloadEqualsTheTemplate) {
  const TetGeometry g = mini::compute_tet_geometry(kX);
  const ElemVec x = test::random_state(31, g, 0.05, 0.1);
  const BubbleVec b(0.01, -0.02, 0.005);
  const Gent gent{0.4, 5.0};
  const auto direct = mini::compute_strain_energy(g, x, gent, 0.05, b);
  const auto visited = mini::compute_strain_energy(g, x, AnyMaterial(gent), 0.05, b);
  EXPECT_EQ(direct.isochoric, visited.isochoric);
  EXPECT_EQ(direct.volumetric, visited.volumetric);
  EXPECT_GT(direct.isochoric, 0.0);
}

}  // namespace
}  // namespace plisse
