// Viscous stabilisation (physics/viscous_damping.hpp, docs/theory/viscous.md): the tangent is the
// derivative of the residual, the force and the dissipated energy of a prescribed motion match
// their closed forms, nothing acts without a time increment, checkpoints restore the state, and
// the model builder creates the term with the wall thickness as length; on a shell's mid-surface
// the same, with the wall's volume lumped by triangles (Z6).
#include "physics/viscous_damping.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "app/model_builder.hpp"
#include "app/wrinkling.hpp"
#include "case/case.hpp"
#include "core/error.hpp"
#include "mesh/generate.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;
using test::random_state;
using test::term_residual;

constexpr double kEta = 0.3;     // [MPa s]
constexpr double kLength = 0.5;  // [mm]

Mesh box() {  // 3 x 2 x 1 mm, volume 6 mm^3
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 3.0;
  spec.width = 2.0;
  spec.thickness = 1.0;
  spec.layers = 2;
  spec.element_size = 1.0;
  return generate_mesh(spec);
}
constexpr double kBoxVolume = 6.0;  // [mm^3]

/// Full state with displacement w at every node and pressure `p` (not touched by the term).
std::vector<double> uniform_state(const Mesh& mesh, const Vec3d& w, double p = 0.0) {
  std::vector<double> x(static_cast<std::size_t>(kValuesPerNode * mesh.n_nodes()));
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    for (int k = 0; k < 3; ++k) x[static_cast<std::size_t>(node_dof(i, k))] = w[k];
    x[static_cast<std::size_t>(node_dof(i, 3))] = p;
  }
  return x;
}

TEST(ViscousDamping, LumpedCoefficientsSumToViscosityTimesVolumeOverLengthSquared) {
  const Mesh mesh = box();
  const ViscousDamping term(mesh, kEta, kLength);
  double sum = 0.0;
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    sum += term.damping_coefficient(i, 0);
    EXPECT_EQ(term.damping_coefficient(i, 1), term.damping_coefficient(i, 0));
    EXPECT_EQ(term.damping_coefficient(i, 2), term.damping_coefficient(i, 0));
  }
  EXPECT_NEAR(sum, kEta * kBoxVolume / (kLength * kLength), 1e-13);
}

/// `term` after a first accepted step at t = 0.1 (so that u^n != 0), linearised in a second one at
/// t = 0.35 at a random state of `scale` [mm]: its tangent there, and the largest difference
/// between it and central differences of the residual.
struct Linearised {
  Eigen::MatrixXd K;
  double error = 0.0;
};
Linearised linearise_after_a_step(ViscousDamping& term, int n, unsigned seed, double scale) {
  term_residual(term, 0.1, random_state(n, seed, 0.5 * scale));
  term.accept_step(random_state(n, seed, 0.5 * scale));
  const auto x = random_state(n, seed + 1, scale);
  DenseSink sink(n);
  std::vector<double> r(static_cast<std::size_t>(n), 0.0);
  term.assemble(0.35, x, r, &sink);
  return {sink.K, test::max_tangent_error(term, 0.35, x, sink.K, 1e-6)};
}

TEST(ViscousDamping, TangentIsDerivativeOfResidual) {
  const Mesh mesh = box();
  ViscousDamping term(mesh, kEta, kLength);
  const auto [K, max_error] = linearise_after_a_step(term, kValuesPerNode * mesh.n_nodes(), 1, 0.2);
  const double scale = K.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(max_error, 1e-8 * scale);  // the residual is linear in x: only rounding remains
  EXPECT_TRUE(K.isApprox(K.transpose(), 0.0));
  // Diagonal c_i / Δt on displacement rows, nothing on pressure rows.
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    EXPECT_NEAR(K(node_dof(i, 0), node_dof(i, 0)), term.damping_coefficient(i, 0) / 0.25,
                1e-12 * scale);
    EXPECT_EQ(K(node_dof(i, 3), node_dof(i, 3)), 0.0);
  }
}

TEST(ViscousDamping, ForceOfAUniformIncrementIsEtaVolumeRateOverLengthSquared) {
  const Mesh mesh = box();
  ViscousDamping term(mesh, kEta, kLength);
  const Vec3d w(0.02, -0.01, 0.03);  // [mm] over Δt = 0.4 s
  const Eigen::VectorXd r = term_residual(term, 0.4, uniform_state(mesh, w, 5.0));
  Vec3d total = Vec3d::Zero();
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    for (int k = 0; k < 3; ++k) total[k] += r(node_dof(i, k));
    EXPECT_EQ(r(node_dof(i, 3)), 0.0);
  }
  const Vec3d expected = kEta * kBoxVolume / (kLength * kLength) * w / 0.4;  // [N]
  EXPECT_NEAR((total - expected).norm(), 0.0, 1e-13 * expected.norm());
}

TEST(ViscousDamping, NothingActsWithoutATimeIncrement) {
  const Mesh mesh = box();
  ViscousDamping term(mesh, kEta, kLength);
  const int n = kValuesPerNode * mesh.n_nodes();
  const auto x = random_state(n, 4, 0.1);
  for (double t : {0.0, -0.5}) {
    DenseSink sink(n);
    std::vector<double> r(n, 0.0);
    term.assemble(t, x, r, &sink);
    EXPECT_EQ(Eigen::Map<Eigen::VectorXd>(r.data(), n).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(sink.K.cwiseAbs().maxCoeff(), 0.0);
  }
  term.accept_step(x);  // Δt = 0: no work
  EXPECT_EQ(term.dissipated_energy(), 0.0);
}

TEST(ViscousDamping, DissipatedEnergyOfALinearMotionMatchesTheClosedForm) {
  // u(t) = v t at every node, uneven steps: each step dissipates c |v Δt|² / Δt = c |v|² Δt, so
  // D(T) = η V |v|² T / ℓ² whatever the steps.
  const Mesh mesh = box();
  ViscousDamping term(mesh, kEta, kLength);
  const Vec3d v(0.1, 0.05, -0.2);  // [mm/s]
  const double times[] = {0.1, 0.15, 0.4, 0.7, 1.0};
  for (double t : times) {
    const auto x = uniform_state(mesh, v * t);
    term_residual(term, t, x);  // the solver's last evaluation at t
    term.accept_step(x);
  }
  const double expected = kEta * kBoxVolume * v.squaredNorm() * 1.0 / (kLength * kLength);
  EXPECT_NEAR(term.dissipated_energy(), expected, 1e-13 * expected);
  EXPECT_EQ(term.history_columns(), std::vector<std::string>{"dissipated_energy"});
  EXPECT_EQ(term.history_values(1.0, uniform_state(mesh, v))[0], term.dissipated_energy());
}

TEST(ViscousDamping, ARejectedTrialDoesNotCount) {
  const Mesh mesh = box();
  ViscousDamping term(mesh, kEta, kLength);
  const Vec3d v(0.1, 0.0, 0.0);
  term_residual(term, 0.5, uniform_state(mesh, 3.0 * v));  // trial step, then cut back
  term.reject_step();
  term_residual(term, 0.25, uniform_state(mesh, 0.25 * v));
  term.accept_step(uniform_state(mesh, 0.25 * v));
  const double expected = kEta * kBoxVolume * v.squaredNorm() * 0.25 / (kLength * kLength);
  EXPECT_NEAR(term.dissipated_energy(), expected, 1e-13 * expected);
}

TEST(ViscousDamping, CheckpointRoundTripContinuesIdentically) {
  const Mesh mesh = box();
  const int n = kValuesPerNode * mesh.n_nodes();
  ViscousDamping original(mesh, kEta, kLength);
  const auto x1 = random_state(n, 5, 0.1), x2 = random_state(n, 6, 0.1);
  term_residual(original, 0.2, x1);
  original.accept_step(x1);
  term_residual(original, 0.5, x2);
  original.accept_step(x2);
  const std::vector<double> saved = original.save_state();
  ASSERT_EQ(saved.size(), static_cast<std::size_t>(2 + 3 * mesh.n_nodes()));

  ViscousDamping restored(mesh, kEta, kLength);
  restored.load_state(saved);
  EXPECT_EQ(restored.dissipated_energy(), original.dissipated_energy());
  EXPECT_GT(restored.dissipated_energy(), 0.0);
  EXPECT_EQ(restored.save_state(), saved);
  const auto x3 = random_state(n, 7, 0.1);
  const Eigen::VectorXd a = term_residual(original, 0.8, x3);
  const Eigen::VectorXd b = term_residual(restored, 0.8, x3);
  EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0.0);
  original.accept_step(x3);
  restored.accept_step(x3);
  EXPECT_EQ(restored.dissipated_energy(), original.dissipated_energy());

  std::vector<double> wrong_size(saved.begin(), saved.end() - 1);
  EXPECT_THROW(restored.load_state(wrong_size), Error);
  std::vector<double> not_finite = saved;
  not_finite[1] = std::nan("");
  EXPECT_THROW(restored.load_state(not_finite), Error);
}

TEST(ViscousDamping, ConstrainedComponentsGetNoForceAndDissipateNothing) {
  // A prescribed motion (e.g. a clamped edge driven by a die) is not resisted by the artificial
  // force, and its work must not show up in D: only the free components count.
  const Mesh mesh = box();
  std::vector<ConstrainedComponent> constraints;
  for (int i = 0; i < mesh.n_nodes(); ++i) constraints.push_back({i, 1, 0.5, Ramp{0.0, 1.0}});
  ViscousDamping term(mesh, kEta, kLength, constraints);
  const Vec3d v(0.1, 0.5, 0.2);  // y prescribed everywhere, x and z free
  const auto x = uniform_state(mesh, v);
  DenseSink sink(kValuesPerNode * mesh.n_nodes());
  std::vector<double> r(x.size(), 0.0);
  term.assemble(1.0, x, r, &sink);
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    EXPECT_EQ(r[static_cast<std::size_t>(node_dof(i, 1))], 0.0);
    EXPECT_EQ(sink.K(node_dof(i, 1), node_dof(i, 1)), 0.0);
    EXPECT_EQ(term.damping_coefficient(i, 1), 0.0);
  }
  term.accept_step(x);
  const double expected = kEta * kBoxVolume * (v.x() * v.x() + v.z() * v.z()) / (kLength * kLength);
  EXPECT_NEAR(term.dissipated_energy(), expected, 1e-13 * expected);
  EXPECT_THROW(ViscousDamping(mesh, kEta, kLength, {{mesh.n_nodes(), 0, 0.0, Ramp{}}}), Error);
}

TEST(ViscousDamping, RejectsNonPositiveParameters) {
  const Mesh mesh = box();
  EXPECT_THROW(ViscousDamping(mesh, 0.0, 1.0), Error);
  EXPECT_THROW(ViscousDamping(mesh, 1.0, 0.0), Error);
  EXPECT_THROW(ViscousDamping(mesh, std::nan(""), 1.0), Error);
  EXPECT_THROW(ViscousDamping(mesh, 1.0, INFINITY), Error);
}

TEST(ViscousDamping, MeanEdgeLengthOfAUnitCubeMesh) {
  // make_box_mesh cuts each cube into 6 tetrahedra: edges of lengths 1, √2 and √3 (Kuhn split:
  // per tetrahedron 3 edges of length 1, 2 face diagonals √2 and 1 body diagonal √3).
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.0;
  spec.divisions = 1;
  const Mesh mesh = generate_mesh(spec);
  EXPECT_NEAR(mean_edge_length(mesh), (3.0 + 2.0 * std::sqrt(2.0) + std::sqrt(3.0)) / 6.0, 1e-14);
}

TEST(ModelBuilder, CreatesViscousDampingWithTheWallThicknessWhenViscosityIsPositive) {
  Case c;
  c.material.model = "neo-hookean";
  c.material.params = {{"c1", 0.5}};
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 3.0;
  spec.width = 2.0;
  spec.thickness = 1.0;
  spec.layers = 2;
  spec.element_size = 1.0;
  c.mesh.generate = spec;
  const Mesh mesh = generate_mesh(spec);
  EXPECT_TRUE(app::build_model_parts(c, mesh).terms.empty());  // viscosity 0: no term
  c.solver.viscosity = kEta;
  const auto terms = std::move(app::build_model_parts(c, mesh).terms);
  ASSERT_EQ(terms.size(), 1u);
  const auto* term = dynamic_cast<const ViscousDamping*>(terms[0].get());
  ASSERT_NE(term, nullptr);
  double sum = 0.0;
  for (int i = 0; i < mesh.n_nodes(); ++i) sum += term->damping_coefficient(i, 1);
  EXPECT_NEAR(sum, kEta * kBoxVolume / (1.0 * 1.0), 1e-13);  // ℓ = thickness = 1 mm
}

// A shell's mid-surface (viscous.md, Z6): the sheet of 3 x 2 mm, 0.1 mm thick, in triangles of
// 0.5 mm. Every corner takes a third of its triangles' area times their thickness: the
// coefficients are positive and sum to η A t / ℓ²; the damping force of a uniform increment is
// then η A t / ℓ² v in total, and the tangent is the derivative of the residual on the shell's
// state as well.
Mesh shell_sheet() {
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 3.0;
  spec.width = 2.0;
  spec.thickness = 0.1;
  spec.element_size = 0.5;
  return generate_shell_surface(spec);
}
constexpr double kShellVolume = 3.0 * 2.0 * 0.1;  // [mm^3]

TEST(ViscousDamping, OnAShellTheCornersShareTheWallsVolumeByThirds) {
  const Mesh mesh = shell_sheet();
  ASSERT_TRUE(mesh.is_shell());
  const ViscousDamping term(mesh, kEta, kLength);
  double sum = 0.0;
  for (int i = 0; i < mesh.n_nodes(); ++i) {
    EXPECT_GT(term.damping_coefficient(i, 0), 0.0) << "node " << i;
    sum += term.damping_coefficient(i, 2);
  }
  EXPECT_NEAR(sum, kEta * kShellVolume / (kLength * kLength), 1e-13);

  ViscousDamping moving(mesh, kEta, kLength);
  const double dt = 0.25;
  const Vec3d w(0.0, 0.0, 0.02);  // a uniform increment normal to the sheet
  const auto x = uniform_state(mesh, w);
  std::vector<double> residual(x.size(), 0.0);
  moving.assemble(dt, x, residual, nullptr);
  double force = 0.0;
  for (int i = 0; i < mesh.n_nodes(); ++i)
    force += residual[static_cast<std::size_t>(node_dof(i, 2))];
  EXPECT_NEAR(force, kEta * kShellVolume / (kLength * kLength) * w.z() / dt, 1e-13);

  // The tangent against central differences, after a first accepted step (u^n != 0).
  ViscousDamping linearised(mesh, kEta, kLength);
  const auto [K, max_error] =
      linearise_after_a_step(linearised, kValuesPerNode * mesh.n_nodes(), 3, 0.02);
  const double scale = K.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(max_error, 1e-8 * scale);  // the residual is linear in x: only rounding remains
}

TEST(ViscousDamping, MeanEdgeLengthOfAShellIsItsTrianglesOwn) {
  // The generated sheet cuts each square cell of 0.5 mm into two right triangles: per triangle two
  // sides of 0.5 mm and a diagonal of 0.5 √2.
  EXPECT_NEAR(mean_edge_length(shell_sheet()), 0.5 * (2.0 + std::sqrt(2.0)) / 3.0, 1e-14);
}

// `solver.viscosity` on a shell case: the model builder adds the term with the wall thickness as ℓ,
// and the clamped edge's nodes get none.
TEST(ModelBuilder, CreatesViscousDampingOnAShellWithItsThickness) {
  const Case c = parse_case_string(
      "element: shell\n"
      "mesh: {generate: sheet, length: 3.0, width: 2.0, thickness: 0.1, element_size: 0.5}\n"
      "material: {model: neo-hookean, c1: 0.2}\n"
      "boundary:\n  - {type: clamped, surface: left}\n"
      "solver: {viscosity: 0.3}\n",
      "c.yaml");
  const Mesh mesh = app::load_perturbed_mesh(c);
  ASSERT_TRUE(mesh.is_shell());
  EXPECT_TRUE(app::unsupported_features(c, mesh).empty());
  const auto terms = std::move(app::build_model_parts(c, mesh).terms);
  ASSERT_EQ(terms.size(), 1u);
  const auto* term = dynamic_cast<const ViscousDamping*>(terms[0].get());
  ASSERT_NE(term, nullptr);
  // ℓ = the thickness, 0.1 mm; the clamped edge x = 0 gets no damping.
  const ViscousDamping free(mesh, kEta, 0.1);
  for (int i = 0; i < mesh.n_nodes(); ++i)
    EXPECT_EQ(term->damping_coefficient(i, 0), mesh.nodes[static_cast<std::size_t>(i)].x() > 0.0
                                                   ? free.damping_coefficient(i, 0)
                                                   : 0.0)
        << "node " << i;
}

}  // namespace
}  // namespace plisse
