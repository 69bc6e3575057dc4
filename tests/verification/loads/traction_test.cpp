// Dead loads through `plisse run` (docs/theory/loads.md, L11-L13):
// - a block under an end traction, whose homogeneous stretch the closed form gives to the solver
//   tolerance with both elements, given per unit area or in total, and whose work converges to
//   the stored energy at second order in the step;
// - a point force balanced by the reaction of a clamped base, and a point off the body refused;
// - Cook's tapered panel in plane strain, nearly incompressible, whose tip deflection converges
//   from below under mesh refinement with both elements.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "mesh/box_mesh.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/second_order.hpp"
#include "output/history_writer.hpp"
#include "support/run_case.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

using test::history_column;
using test::run_case_text;

// --- A block under an end traction ------------------------------------------------------------

constexpr double kC1 = 0.25;       // neo-Hookean c1 [MPa]
constexpr double kTraction = 1.0;  // [MPa] per undeformed area, on the 5 x 5 mm top

/// Uniaxial dead load on an incompressible neo-Hookean block: the nominal stress
/// P = 2 c1 (λ − λ^-2) equals the traction per undeformed area (Ogden, Non-linear Elastic
/// Deformations, 1984, section 7.2). Solved for λ by Newton.
double stretch_under(double P) {
  double l = 1.0;
  for (int k = 0; k < 50; ++k)
    l -= (2 * kC1 * (l - 1 / (l * l)) - P) / (2 * kC1 * (1 + 2 / (l * l * l)));
  return l;
}

std::string block_case(const std::string& element, const std::string& load, int steps,
                       const std::string& type = "traction") {
  return "element: " + element +
         "\n"
         "mesh: {generate: cube, edge: 5.0, divisions: 2}\n"
         "material: {model: neo-hookean, c1: 0.25}\n"
         "boundary:\n"
         "  - {type: symmetry, surface: sym_x}\n"
         "  - {type: symmetry, surface: sym_y}\n"
         "  - {type: symmetry, surface: sym_z}\n"
         "loads:\n"
         "  - {type: " +
         type + ", name: pull, surface: top, " + load +
         "}\n"
         "solver:\n"
         "  steps: " +
         std::to_string(steps) + "\n  max_step: " + std::to_string(1.0 / steps) +
         "\n"
         "  newton: {rtol: 1.0e-11, atol: 1.0e-13, max_iterations: 20}\n"
         "output: {stretch_axis: z}\n";
}

void expect_closed_form_block(const std::string& element, const std::string& load) {
  const auto dir = test::scratch_directory("traction-block-" + element + "-" +
                                           std::to_string(std::hash<std::string>{}(load) % 1000));
  const HistoryTable h = run_case_text(dir, block_case(element, load, 4));
  ASSERT_EQ(h.rows.size(), 4u);
  const std::size_t factor = history_column(h, "load_factor"),
                    stretch = history_column(h, "stretch"), lz = history_column(h, "load_z:pull"),
                    lx = history_column(h, "load_x:pull"), sxx = history_column(h, "cauchy_xx"),
                    szz = history_column(h, "cauchy_zz");
  for (const auto& row : h.rows) {
    const double P = row[factor] * kTraction;
    const double l = stretch_under(P);
    EXPECT_NEAR(row[stretch], l, 1e-9 * l) << element << ", load factor " << row[factor];
    EXPECT_NEAR(row[szz], l * P, 1e-8 * l * P) << "Cauchy stress = λ P";
    EXPECT_NEAR(row[sxx], 0.0, 1e-8 * l * P) << "free lateral faces";
    EXPECT_NEAR(row[lz], 25.0 * P, 1e-12 * 25.0) << "applied force = traction x area";
    EXPECT_EQ(row[lx], 0.0);
  }
  EXPECT_NEAR(h.rows.back()[stretch], 2.2055694304, 1e-9);  // stretch_under(1) to 11 digits
}

TEST(EndTraction, BlockStretchesAsTheClosedFormWithMini) {
  expect_closed_form_block("mini", "traction: [0, 0, 1.0]");
}
TEST(EndTraction, BlockStretchesAsTheClosedFormWithTaylorHood) {
  expect_closed_form_block("taylor-hood", "traction: [0, 0, 1.0]");
}
TEST(EndTraction, TotalForceOnTheFaceIsTheSameLoadAsItsTraction) {
  expect_closed_form_block("mini", "force: [0, 0, 25.0]");
  expect_closed_form_block("taylor-hood", "force: [0, 0, 25.0]");
}

TEST(EndTraction, WorkConvergesToTheStoredEnergyAtSecondOrderInTheStep) {
  // The load does work ∫ F du on a conservative body: at equilibrium it equals the strain energy
  // c1 (λ^2 + 2/λ − 3) V0. The history's trapezoidal sum (L13) has an error O(Δt^2): halving the
  // step divides it by 4.
  double error[2];
  for (int k = 0; k < 2; ++k) {
    const int steps = 5 << k;
    const HistoryTable h =
        run_case_text(test::scratch_directory("traction-work-" + std::to_string(steps)),
                      block_case("mini", "traction: [0, 0, 1.0]", steps));
    ASSERT_EQ(h.rows.size(), static_cast<std::size_t>(steps));
    const double l = h.rows.back()[history_column(h, "stretch")];
    const double stored = kC1 * (l * l + 2 / l - 3) * 125.0;
    EXPECT_NEAR(h.rows.back()[history_column(h, "strain_energy")], stored, 1e-8 * stored);
    error[k] = h.rows.back()[history_column(h, "work:pull")] - stored;
  }
  EXPECT_LT(std::abs(error[1]), 0.01 * 86.6) << "within 1 % with 10 steps";
  const double ratio = error[0] / error[1];
  EXPECT_GT(ratio, 3.6) << "errors " << error[0] << ", " << error[1];
  EXPECT_LT(ratio, 4.4) << "errors " << error[0] << ", " << error[1];
}

TEST(FollowerNormalTraction, IsTheCauchyStressOfTheBlockWithBothElements) {
  // A follower traction T along the deformed normal acts per unit deformed area: it is the Cauchy
  // stress σ_zz = 2 c1 (λ^2 − 1/λ) of the homogeneous stretch, and its resultant T times the
  // deformed face area 25/λ mm^2 (the lateral stretches are 1/sqrt(λ)).
  for (const std::string element : {"mini", "taylor-hood"}) {
    const HistoryTable h =
        run_case_text(test::scratch_directory("follower-normal-" + element),
                      block_case(element, "normal: 1.0", 4, "follower-traction"));
    ASSERT_EQ(h.rows.size(), 4u);
    for (const auto& row : h.rows) {
      const double T = row[history_column(h, "load_factor")] * kTraction;
      double l = 1.0;  // Newton on 2 c1 (λ^2 − 1/λ) = T
      for (int k = 0; k < 50; ++k)
        l -= (2 * kC1 * (l * l - 1 / l) - T) / (2 * kC1 * (2 * l + 1 / (l * l)));
      EXPECT_NEAR(row[history_column(h, "stretch")], l, 1e-9 * l) << element << ", T = " << T;
      EXPECT_NEAR(row[history_column(h, "cauchy_zz")], T, 1e-8 * T) << element;
      EXPECT_NEAR(row[history_column(h, "load_z:pull")], T * 25.0 / l, 1e-9 * T * 25.0) << element;
    }
  }
}

// --- A point force ----------------------------------------------------------------------------

TEST(PointForce, ClampedBaseCarriesTheForceAndTheLogNamesTheNode) {
  for (const std::string element : {"mini", "taylor-hood"}) {
    const auto dir = test::scratch_directory("point-force-" + element);
    const HistoryTable h =
        run_case_text(dir, "element: " + element +
                               "\n"
                               "mesh: {generate: cube, edge: 5.0, divisions: 2}\n"
                               "material: {model: neo-hookean, c1: 0.25}\n"
                               "boundary: [{type: fixed, name: base, surface: bottom}]\n"
                               "loads:\n"
                               "  - {type: point-force, name: tip, point: [2.5, 2.6, 5.1],"
                               " force: [0.2, -0.1, -0.5]}\n"
                               "probes: [{name: node, point: [2.5, 2.5, 5.0],"
                               " fields: [position]}]\n"
                               "solver: {steps: 2, newton: {rtol: 1.0e-12, atol: 1.0e-14}}\n");
    ASSERT_FALSE(h.rows.empty());
    const auto& last = h.rows.back();
    const double F[3] = {0.2, -0.1, -0.5};
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      // Equilibrium: the reaction of the base balances the force, to the Newton tolerance.
      EXPECT_NEAR(last[history_column(h, std::string("force_") + axes[i] + ":base")], -F[i], 1e-9)
          << element << " component " << axes[i];
      EXPECT_DOUBLE_EQ(last[history_column(h, std::string("load_") + axes[i] + ":tip")], F[i]);
    }
    // And its moment about the origin balances the force's, which acts at the loaded node's
    // current position (the probe on that node): moment_<axis>:base = -(x × F).
    const Vec3d x(last[history_column(h, "x:node")], last[history_column(h, "y:node")],
                  last[history_column(h, "z:node")]);
    EXPECT_GT((x - Vec3d(2.5, 2.5, 5.0)).norm(), 0.1) << "the node should move";
    const Vec3d moment = -x.cross(Vec3d(F[0], F[1], F[2]));
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(last[history_column(h, std::string("moment_") + axes[i] + ":base")], moment[i],
                  1e-9)
          << element << " component " << axes[i];
    std::ifstream log(dir / "run" / "log.txt");
    const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("load 'tip': on node"), std::string::npos) << text;
    EXPECT_NE(text.find("at [2.5, 2.5, 5], 0.141 mm from its point"), std::string::npos) << text;
  }
}

TEST(PointForce, PointOffTheBodyIsRefusedByRunAndCheck) {
  const auto dir = test::scratch_directory("point-force-off");
  fs::create_directories(dir);
  std::ofstream(dir / "case.yaml")
      << "mesh: {generate: cube, edge: 5.0, divisions: 2}\n"
         "material: {model: neo-hookean, c1: 0.25}\n"
         "boundary: [{type: fixed, surface: bottom}]\n"
         "loads: [{type: point-force, name: tip, point: [2.5, 2.5, 50], force: [0, 0, 1]}]\n";
  for (const std::string command : {"run", "check"}) {
    const auto r = test::run_plisse_captured(
        command + " " + (dir / "case.yaml").string() +
        (command == "run" ? " -o " + (dir / "run").string() : std::string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("is 45 mm from the nearest node [2.5, 2.5, 5]"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("give a point on the body"), std::string::npos) << r.output;
  }
}

// --- Cook's tapered panel ---------------------------------------------------------------------

/// Cook's membrane (Cook, Malkus & Plesha, Concepts and Applications of Finite Element Analysis,
/// 1989): the panel with corners (0, 0), (48, 44), (48, 60), (0, 44) mm, one cell thick along z
/// between two symmetry planes (plane strain), `n` x `n` cells mapped bilinearly from the unit
/// square; second order with straight edges when `order` is 2.
fs::path write_cook_mesh(const fs::path& dir, int n, int order) {
  Mesh mesh = make_box_mesh({1.0, 1.0, 1.0}, {n, n, 1}, 1);
  for (Vec3d& X : mesh.nodes) {
    const double s = X.x(), t = X.y();
    X = Vec3d(48.0 * s, 44.0 * s + t * (44.0 - 28.0 * s), X.z());
  }
  if (order == 2) add_straight_edge_nodes(mesh);
  fs::create_directories(dir);
  const fs::path path = dir / "cook.msh";
  write_gmsh(mesh, path.string());
  return path;
}

/// The tip deflection [mm] at (48, 60) of Cook's panel, clamped at x = 0, under a total shear
/// force of 32 N along y on the face x = 48, nearly incompressible neo-Hookean (μ = 80.194 MPa,
/// κ = 400942 MPa: ν = 0.4999).
double cook_tip_deflection(const std::string& element, int n) {
  const auto dir = test::scratch_directory("cook-" + element + "-" + std::to_string(n));
  const fs::path mesh = write_cook_mesh(dir, n, element == "mini" ? 1 : 2);
  const HistoryTable h = run_case_text(
      dir, "element: " + element + "\nmesh: {file: " + mesh.string() +
               "}\n"
               "material: {model: neo-hookean, c1: 40.097, incompressibility: nearly,"
               " bulk_modulus: 400942}\n"
               "boundary:\n"
               "  - {type: fixed, surface: left}\n"
               "  - {type: symmetry, surface: bottom}\n"
               "  - {type: symmetry, surface: top}\n"
               "loads: [{type: traction, name: shear, surface: right, force: [0, 32, 0]}]\n"
               "probes: [{name: tip, point: [48, 60, 0]}]\n"
               "solver: {steps: 4, newton: {rtol: 1.0e-10, atol: 1.0e-12}}\n");
  if (h.rows.empty()) return NAN;
  EXPECT_NEAR(h.rows.back()[history_column(h, "load_y:shear")], 32.0, 1e-12);
  return h.rows.back()[history_column(h, "uy:tip")];
}

/// The limit of a sequence converging geometrically (Richardson / Aitken from its last three
/// values): u_3 + d_3 r / (1 − r), d_k = u_k − u_k-1, r = d_3 / d_2.
double extrapolated(const std::vector<double>& u) {
  const std::size_t k = u.size() - 1;
  const double d2 = u[k - 1] - u[k - 2], d3 = u[k] - u[k - 1];
  const double r = d3 / d2;
  return u[k] + d3 * r / (1.0 - r);
}

TEST(CookMembrane, TipDeflectionConvergesFromBelowWithBothElements) {
  // Measured tip deflections [mm]: MINI n = 4, 8, 16, 32: 1.1331, 1.8318, 2.2333, 2.3801;
  // Taylor-Hood n = 2, 4, 8, 16: 2.0816, 2.3303, 2.4090, 2.4409. Both rise with every
  // refinement (the coarse meshes are too stiff), the steps shrink (ratios 0.57 and 0.37 for
  // MINI, 0.32 and 0.40 for Taylor-Hood: the clamped corners keep the rate below 2), and the
  // extrapolated limits of the two element families agree to 0.2 % (2.466 and 2.462 mm).
  std::vector<double> limit;
  for (const std::string element : {"mini", "taylor-hood"}) {
    std::vector<double> u;
    for (int n : element == "mini" ? std::vector<int>{4, 8, 16, 32} : std::vector<int>{2, 4, 8, 16})
      u.push_back(cook_tip_deflection(element, n));
    for (std::size_t k = 1; k < u.size(); ++k) {
      EXPECT_GT(u[k], u[k - 1]) << element << ": converges from below, refinement " << k;
      if (k >= 2) {
        EXPECT_LT(u[k] - u[k - 1], 0.7 * (u[k - 1] - u[k - 2]))
            << element << ": the steps shrink, refinement " << k;
      }
    }
    limit.push_back(extrapolated(u));
    EXPECT_GT(limit.back(), u.back()) << element;
  }
  EXPECT_NEAR(limit[0], limit[1], 0.01 * limit[1]) << "MINI and Taylor-Hood tend to one limit";
}

}  // namespace
}  // namespace plisse
