// Cavity term (docs/theory/cavities.md, C6-C11): the bordered tangent is the derivative of the
// residual (central differences, both controls, random states), it is symmetric exactly when the
// term says so, and the constraint row states the prescribed volume and the ideal-gas law.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>

#include "mesh/generate.hpp"
#include "physics/cavity.hpp"
#include "physics/cavity_volume.hpp"
#include "physics/surface.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;

Mesh small_shell(Symmetry symmetry) {
  MeshGenerationSpec spec;
  spec.kind = "spherical-shell";
  spec.inner_radius = 10.0;
  spec.thickness = 1.0;
  spec.layers = 1;
  spec.element_size = 4.0;
  spec.symmetry = symmetry;
  return generate_mesh(spec);
}

/// Zero normal displacement on the symmetry planes sym_x, sym_y, sym_z that the mesh has.
std::vector<ConstrainedComponent> symmetry_constraints(const Mesh& mesh) {
  std::vector<ConstrainedComponent> out;
  const char* tags[3] = {"sym_x", "sym_y", "sym_z"};
  for (int k = 0; k < 3; ++k) {
    if (!mesh.has_surface(tags[k])) continue;
    std::set<int> nodes;
    for (int t : mesh.surface_tags.at(tags[k]))
      nodes.insert(mesh.triangles[t].begin(), mesh.triangles[t].end());
    for (int v : nodes) out.push_back({v, k, 0.0, Ramp{}});
  }
  return out;
}

/// The surfaces of a `symmetry` condition on each of the mesh's planes sym_x, sym_y, sym_z.
std::vector<std::string> symmetry_surfaces(const Mesh& mesh) {
  std::vector<std::string> out;
  for (const char* tag : {"sym_x", "sym_y", "sym_z"})
    if (mesh.has_surface(tag)) out.emplace_back(tag);
  return out;
}

Cavity make_cavity(CavityControl control) {
  Cavity c;
  c.name = "balloon";
  c.surface = {"inner", InputPlace{}};
  c.control = control;
  c.volume_ratio = 3.0;
  c.initial_pressure = 0.02;
  c.mass_ratio = 2.0;
  c.ambient_pressure = 0.1;
  c.ramp = Ramp{0.0, 1.0};
  return c;
}

/// A random state: displacements in [-scale, scale] (zero on constrained components), cavity
/// pressure p_c in [0.01, 0.09] MPa.
std::vector<double> random_state(const Mesh& mesh, const std::vector<ConstrainedComponent>& fixed,
                                 unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  std::vector<double> x(kValuesPerNode * mesh.n_nodes() + 1, 0.0);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) x[node_dof(v, i)] = u(rng);
  for (const auto& c : fixed) x[node_dof(c.node, c.component)] = 0.0;
  x.back() = std::uniform_real_distribution<double>(0.01, 0.09)(rng);
  return x;
}

Eigen::VectorXd residual(CavityTerm& term, double t, const std::vector<double>& x) {
  std::vector<double> r(x.size(), 0.0);
  term.assemble(t, x, r, nullptr);
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

struct CavitySetup {
  Mesh mesh;
  std::vector<ConstrainedComponent> constraints;
  std::unique_ptr<CavityTerm> term;
  int n = 0;
};

CavitySetup make_setup(Symmetry symmetry, CavityControl control, bool constrain) {
  CavitySetup s;
  s.mesh = small_shell(symmetry);
  if (constrain) s.constraints = symmetry_constraints(s.mesh);
  s.term = std::make_unique<CavityTerm>(make_cavity(control), s.mesh, s.constraints,
                                        mirror_planes(symmetry_surfaces(s.mesh), s.mesh));
  s.n = kValuesPerNode * s.mesh.n_nodes() + 1;
  s.term->set_first_global_dof(s.n - 1);
  return s;
}

/// Largest |FD - tangent| in each block of the bordered tangent (uu, u p_c, p_c u, p_c p_c),
/// relative to the largest tangent entry of that block (their units differ: N/mm, mm^2, mm^5/N).
std::array<double, 4> tangent_errors(CavityTerm& term, double t, const std::vector<double>& x,
                                     double h) {
  const int n = static_cast<int>(x.size()), m = n - 1;
  DenseSink sink(n);
  std::vector<double> r(n, 0.0);
  term.assemble(t, x, r, &sink);
  Eigen::MatrixXd fd(n, n);
  for (int j = 0; j < n; ++j) {
    auto xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    fd.col(j) = (residual(term, t, xp) - residual(term, t, xm)) / (2 * h);
  }
  const Eigen::MatrixXd e = (fd - sink.K).cwiseAbs(), k = sink.K.cwiseAbs();
  const auto rel = [](double error, double scale) { return scale > 0 ? error / scale : error; };
  return {rel(e.topLeftCorner(m, m).maxCoeff(), k.topLeftCorner(m, m).maxCoeff()),
          rel(e.topRightCorner(m, 1).maxCoeff(), k.topRightCorner(m, 1).maxCoeff()),
          rel(e.bottomLeftCorner(1, m).maxCoeff(), k.bottomLeftCorner(1, m).maxCoeff()),
          rel(e(m, m), k(m, m))};
}

class CavityTangent : public ::testing::TestWithParam<CavityControl> {};

TEST_P(CavityTangent, IsTheDerivativeOfTheResidualAtRandomStates) {
  CavitySetup s = make_setup(Symmetry::octant, GetParam(), false);
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto x = random_state(s.mesh, {}, seed, 0.5);
    // The displacement residual is cubic in (x, p_c), the volume cubic in x and the gas law
    // smooth in p_c: central differences are O(h^2) = 1e-10 relative, plus round-off.
    const auto errors = tangent_errors(*s.term, 0.6, x, 1e-5);
    std::printf("control %s, seed %u: relative FD error uu %.1e, u-p %.1e, p-u %.1e, p-p %.1e\n",
                GetParam() == CavityControl::volume ? "volume" : "gas", seed, errors[0], errors[1],
                errors[2], errors[3]);
    // p-p (gas): truncation h^2 / (p_c + p_amb)^2 <= 1e-8; the other blocks are near round-off.
    for (double e : errors) EXPECT_LT(e, 1e-7) << "seed " << seed;
  }
}

TEST_P(CavityTangent, IsSymmetricWhenTheSymmetryPlanesAreConstrained) {
  CavitySetup s = make_setup(Symmetry::octant, GetParam(), true);
  EXPECT_TRUE(s.term->symmetric());
  const auto x = random_state(s.mesh, s.constraints, 4, 0.5);
  DenseSink sink(s.n);
  std::vector<double> r(s.n, 0.0);
  s.term->assemble(0.6, x, r, &sink);
  // Only the free components enter the solver's matrix.
  std::vector<bool> free(s.n, true);
  for (const auto& c : s.constraints) free[node_dof(c.node, c.component)] = false;
  // Blocks relative to their own scale: uu [N/mm], the border (row vs column) [mm^2].
  const int m = s.n - 1;
  double asymmetry_uu = 0.0, asymmetry_border = 0.0, scale_uu = 0.0, scale_border = 0.0;
  for (int i = 0; i < m; ++i) {
    if (!free[i]) continue;
    scale_border = std::max(scale_border, std::abs(sink.K(i, m)));
    asymmetry_border = std::max(asymmetry_border, std::abs(sink.K(i, m) - sink.K(m, i)));
    for (int j = 0; j < m; ++j)
      if (free[j]) {
        scale_uu = std::max(scale_uu, std::abs(sink.K(i, j)));
        asymmetry_uu = std::max(asymmetry_uu, std::abs(sink.K(i, j) - sink.K(j, i)));
      }
  }
  EXPECT_LT(asymmetry_uu, 1e-13 * scale_uu);
  EXPECT_LT(asymmetry_border, 1e-13 * scale_border);
  // The border is not empty: the wall's nodes feel the cavity pressure (c/6 ~ a third of a
  // triangle's area, several mm^2 here).
  EXPECT_GT(scale_border, 1.0);
}

TEST_P(CavityTangent, IsNotSymmetricWhenTheSymmetryPlanesAreFree) {
  CavitySetup s = make_setup(Symmetry::octant, GetParam(), false);
  EXPECT_FALSE(s.term->symmetric());
  const auto x = random_state(s.mesh, {}, 5, 0.5);
  DenseSink sink(s.n);
  std::vector<double> r(s.n, 0.0);
  s.term->assemble(0.6, x, r, &sink);
  EXPECT_GT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(),
            1e-3 * sink.K.cwiseAbs().maxCoeff());
}

TEST_P(CavityTangent, IsSymmetricOnAClosedSurfaceWithoutConstraints) {
  CavitySetup s = make_setup(Symmetry::full, GetParam(), false);
  EXPECT_TRUE(s.term->symmetric());
  const auto x = random_state(s.mesh, {}, 6, 0.5);
  DenseSink sink(s.n);
  std::vector<double> r(s.n, 0.0);
  s.term->assemble(0.6, x, r, &sink);
  EXPECT_LT((sink.K - sink.K.transpose()).cwiseAbs().maxCoeff(),
            1e-13 * sink.K.cwiseAbs().maxCoeff());
  // Uniform pressure on a closed wall: no net force.
  Vec3d resultant = Vec3d::Zero();
  for (int v = 0; v < s.mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) resultant[i] += r[node_dof(v, i)];
  EXPECT_LT(resultant.norm(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Controls, CavityTangent,
                         ::testing::Values(CavityControl::volume, CavityControl::gas),
                         [](const auto& info) {
                           return std::string(info.param == CavityControl::volume ? "volume"
                                                                                  : "gas");
                         });

TEST(CavityTerm, ConstraintRowIsThePrescribedVolume) {
  CavitySetup s = make_setup(Symmetry::octant, CavityControl::volume, true);
  const double V0 = s.term->reference_volume();
  std::vector<double> x(s.n, 0.0);
  // Half-way up the ramp to volume_ratio 3 the target is 2 V0; at u = 0 the row is -(V0 - 2 V0).
  EXPECT_NEAR(residual(*s.term, 0.5, x)[s.n - 1], V0, 1e-12 * V0);
  // The octant is closed by three mirror planes: the whole balloon holds 8 times its volume.
  EXPECT_EQ(
      s.term->history_columns(),
      (std::vector<std::string>{"pressure:balloon", "volume:balloon", "full_volume:balloon"}));
  x.back() = 0.25;
  const auto h = s.term->history_values(0.5, x);
  EXPECT_EQ(h[0], 0.25);
  EXPECT_NEAR(h[1], V0, 1e-12 * V0);
  EXPECT_EQ(h[2], 8.0 * h[1]);
}

TEST(CavityTerm, ConstraintRowVanishesWhereTheIdealGasLawHolds) {
  CavitySetup s = make_setup(Symmetry::octant, CavityControl::gas, true);
  const double V0 = s.term->reference_volume();
  // p0 = 0.02, p_amb = 0.1 MPa, mass ratio 2: at t = 0.5 the mass is 1.5 times the initial one.
  // Uniform stretch 1.2: (p + 0.1) 1.2^3 V0 = 0.12 * 1.5 V0 gives p = 0.18 / 1.728 - 0.1.
  const double s3 = 1.2 * 1.2 * 1.2, p = 0.18 / s3 - 0.1;
  std::vector<double> x(s.n, 0.0);
  for (int v = 0; v < s.mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) x[node_dof(v, i)] = 0.2 * s.mesh.nodes[v][i];
  x.back() = p;
  EXPECT_NEAR(residual(*s.term, 0.5, x)[s.n - 1], 0.0, 1e-12 * V0);
  x.back() = p + 0.01;  // more pressure: the gas takes less volume than the cavity has
  EXPECT_LT(residual(*s.term, 0.5, x)[s.n - 1], -1e-3 * V0);
  x.back() = -0.1;  // zero absolute pressure is refused
  EXPECT_THROW(residual(*s.term, 0.5, x), Error);
}

// A polytropic gas (gamma = 1.4, adiabatic air) that also fills a rigid reservoir of half the
// whole balloon's volume (cavities.md, C9): its row vanishes where (p + p_amb) ((V + V_r) /
// m)^gamma equals its initial value, with the octant holding an eighth of the reservoir, and the
// bordered tangent is the derivative of the residual.
TEST(CavityTerm, PolytropicGasWithAReservoirKeepsItsLawAndItsTangent) {
  Mesh mesh = small_shell(Symmetry::octant);
  const auto constraints = symmetry_constraints(mesh);
  const int mirrors = mirror_planes(symmetry_surfaces(mesh), mesh);
  Cavity cavity = make_cavity(CavityControl::gas);
  cavity.gamma = 1.4;
  const double v_full = 8.0 * CavityTerm(cavity, mesh, constraints, mirrors).reference_volume();
  cavity.reservoir_volume = 0.5 * v_full;
  CavityTerm term(cavity, mesh, constraints, mirrors);
  const int n = kValuesPerNode * mesh.n_nodes() + 1;
  term.set_first_global_dof(n - 1);
  const double V0 = term.reference_volume(), Vr = cavity.reservoir_volume / 8.0;
  EXPECT_DOUBLE_EQ(term.modelled_reservoir(), Vr);
  // Uniform stretch 1.2 at t = 0.5 (mass 1.5 times the initial): the pressure of the law.
  const double s3 = 1.2 * 1.2 * 1.2, m = 1.5;
  const double p = 0.12 * std::pow((V0 + Vr) * m / (s3 * V0 + Vr), 1.4) - 0.1;
  std::vector<double> x(n, 0.0);
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) x[node_dof(v, i)] = 0.2 * mesh.nodes[v][i];
  x.back() = p;
  EXPECT_NEAR(residual(term, 0.5, x)[n - 1], 0.0, 1e-12 * V0);
  // Without the reservoir the same state holds less gas: the row is off.
  Cavity alone = cavity;
  alone.reservoir_volume = 0.0;
  CavityTerm smaller(alone, mesh, constraints, mirrors);
  smaller.set_first_global_dof(n - 1);
  EXPECT_GT(std::abs(residual(smaller, 0.5, x)[n - 1]), 1e-3 * V0);
  for (unsigned seed : {8u, 9u}) {
    const auto y = random_state(mesh, constraints, seed, 0.5);
    const auto errors = tangent_errors(term, 0.6, y, 1e-5);
    for (double e : errors) EXPECT_LT(e, 1e-7) << "seed " << seed;
  }
}

// A cavity that starts flat holds no gas of its own (C8), but a reservoir's: with one it is
// accepted, starts at V_c = 0 and the gas pushed out of the reservoir fills it as the mass grows.
TEST(CavityTerm, AFlatCavityTakesAGasThatStartsInAReservoir) {
  MeshGenerationSpec spec;
  spec.kind = "sheet";
  spec.length = 4.0;
  spec.width = 4.0;
  spec.thickness = 0.5;
  spec.layers = 1;
  spec.element_size = 2.0;
  const Mesh mesh = generate_mesh(spec);
  Cavity cavity = make_cavity(CavityControl::gas);
  cavity.surface = {"bottom", InputPlace{}};
  EXPECT_THROW(CavityTerm(cavity, mesh, {}, 0), InputError);
  cavity.reservoir_volume = 100.0;
  const CavityTerm term(cavity, mesh, {}, 0);
  EXPECT_EQ(term.reference_volume(), 0.0);
  EXPECT_NEAR(term.fluid_volume(cavity.initial_pressure, 0.0), 0.0, 1e-13);
  // Mass ratio 2 at the end of the ramp, at the initial pressure: the reservoir's gas doubles.
  EXPECT_NEAR(term.fluid_volume(cavity.initial_pressure, 1.0), 100.0, 1e-12);
}

TEST(CavityTerm, CouplingsCoverEveryTangentEntryOutsideTheNodalBlock) {
  CavitySetup s = make_setup(Symmetry::octant, CavityControl::gas, false);
  std::vector<std::pair<int, int>> pairs;
  s.term->add_couplings(pairs);
  const std::set<std::pair<int, int>> listed(pairs.begin(), pairs.end());
  const auto x = random_state(s.mesh, {}, 7, 0.5);
  DenseSink sink(s.n);
  std::vector<double> r(s.n, 0.0);
  s.term->assemble(0.6, x, r, &sink);
  const int pc = s.n - 1;
  for (int j = 0; j < s.n; ++j) {
    if (sink.K(pc, j) != 0.0) {
      EXPECT_TRUE(listed.count({pc, j})) << "row p_c, column " << j;
    }
    if (sink.K(j, pc) != 0.0) {
      EXPECT_TRUE(listed.count({j, pc})) << "row " << j << ", column p_c";
    }
  }
  EXPECT_TRUE(listed.count({pc, pc}));
}

}  // namespace
}  // namespace plisse
