// Large-rotation benchmarks of Sze, Liu & Lo 2004 ("Popular benchmark problems for geometric
// nonlinear analysis of shells", Finite Elements in Analysis and Design 40, 1551–1569) on the
// rotation-free shell triangle (docs/theory/shell.md): the slit annular plate under a lifting line
// force (their section 3.3), the hemisphere with an 18° hole under alternating radial forces (3.4)
// and the pull-out of an open-ended cylinder (3.5), followed under load control through the load
// levels of their tables.
//
// Reference numbers. Sze et al. tabulate, for each problem, the displacements of a few points at
// P/Pmax = 0.05, 0.1, ... 1, computed with ABAQUS's S4R shell on fine meshes (10 x 80 elements on
// the plate and 24 x 36 on the cylinder's octant, as the transcriptions below say). The values
// here are those of P/Pmax = 0.1, 0.2, ... 1, copied from two public transcriptions of the tables,
// each named at its array:
//   - the plate and the cylinder: the reference data of the MBDyn project's test suite for
//     sections 3.3 and 3.5 ("results from [Sze et al. 2004]"), whose models also give the
//     points (A on the inner and B on the outer radius of the loaded side of the slit; A under the
//     cylinder's load, B at mid-length and C at the free edge, 90° from A);
//   - the hemisphere: the reference results of the Elmer project's open-hemisphere shell test
//     ("Reference results from the paper Sze KY, Liu XH, Lo SH ..."), columns P/Pmax and two
//     displacements without labels. The larger one is the point the load pushes in and the smaller
//     the point it pulls out: a ring pulled apart at two points straightens and stiffens, pushed in
//     it folds. The runs agree: on 64 x 64 cells the pulled point moves within 1 % of the smaller
//     column and the pushed one within 2.1 % of the larger at every level, while the two columns
//     differ by up to a factor 2.
//
// Material. Sze et al.'s shells are linear elastic (E, ν). plisse's neo-Hookean with c1 = μ/2 and
// the bulk modulus κ = E / (3 (1 - 2ν)) (shell_fixtures.hpp, `Elastic`) is linear elasticity with E
// and ν at small strain; the problems have large rotations but small strains, and at a strain ε
// two hyperelastic models with the same E and ν (or one of them and a linear law in some strain
// measure) differ in stress by a part of relative size O(ε). The test measures both: the largest
// principal strain |λ - 1| over the elements' faces at the full load, and the change of every
// compared displacement when the neo-Hookean is replaced by a Mooney–Rivlin (c1 = c2 = μ/4, the
// same μ and κ, a different response beyond small strain). The strains stay below 3e-3 on the
// plate and reach 2e-2 (hemisphere) and 0.29 (cylinder) only at the point loads; the change of
// model moves the displacements by 4e-6, 1e-5 and 5.5e-3: under the 2 % tolerance (numbers at each
// test and in shell.md, section 9).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "material/registry.hpp"
#include "mesh/shell_surface.hpp"
#include "physics/dead_load.hpp"
#include "physics/dirichlet.hpp"
#include "shell_fixtures.hpp"
#include "solver/load_stepper.hpp"
#include "solver/mixed_model.hpp"

namespace plisse {
namespace {

using shell_test::Elastic;
using shell_test::mapped_surface;
using shell_test::symmetry;

constexpr double kPi = std::numbers::pi;
/// The largest load step, as a fraction of Pmax (steps are cut back when Newton fails).
constexpr double kMaxStep = 0.1;
/// How much farther from the table than the coarser mesh the finer may be at a level.
constexpr double kMargin = 5e-3;

/// The small-strain-equivalent hyperelastic model that stands for Sze et al.'s linear material.
enum class Model { neo_hookean, mooney_rivlin };

AnyMaterial material_of(const Elastic& elastic, Model model) {
  if (model == Model::neo_hookean) return make_material("neo-hookean", {{"c1", elastic.c1()}});
  return make_material("mooney-rivlin", {{"c1", elastic.c1() / 2.0},
                                         {"c2", elastic.c1() / 2.0}});  // μ = 2 (c1 + c2)
}

/// A table of Sze et al. 2004: the load levels P/Pmax and, per level, the displacements.
struct Table {
  std::vector<double> levels;
  std::vector<std::vector<double>> values;
};

/// The displacements a benchmark reads from a state.
using Reader = std::function<std::vector<double>(const std::vector<double>&)>;

/// A followed load path on one mesh.
struct Curve {
  std::vector<std::vector<double>> values;  ///< per level of the table, the displacements
  double largest_strain = 0.0;  ///< max |λ - 1| over the faces' principal stretches at the end
  double seconds = 0.0;
  int nodes = 0;
  int steps = 0;
  bool completed = false;
};

/// Follows the load path of the shell `mesh` (its loads ramped linearly over t in [0, 1], so that
/// t is P/Pmax) under load control, Newton at each step, through every level of `levels` in turn
/// (each an exact end of a load stepping, its steps at most `max_step`, cut back when Newton
/// fails; Newton stops at `atol` [N] or 1e-9 of the step's first residual), and reads the
/// displacements at each. Fails the calling test when a level is not reached.
Curve follow_path(const Mesh& mesh, AnyMaterial material, double inverse_bulk_modulus,
                  std::vector<ConstrainedComponent> constraints,
                  std::vector<std::unique_ptr<ModelTerm>> terms, const std::vector<double>& levels,
                  double max_step, double atol, const Reader& read) {
  const auto start = std::chrono::steady_clock::now();
  Curve curve;
  curve.nodes = mesh.n_nodes();
  MixedModel model(mesh, std::move(material), inverse_bulk_modulus, std::move(constraints),
                   std::move(terms), ElementFamily::shell);
  std::optional<StepperState> reached;
  for (const double level : levels) {
    SteppingSettings settings;
    settings.end_time = level;
    settings.steps = std::max(1, static_cast<int>(std::ceil(level / max_step - 1e-9)));
    settings.max_step = std::min(1.0, max_step / level);
    settings.newton.rtol = 1e-9;
    settings.newton.atol = atol;
    // The full Newton step: from the flat plate (and at every large rotation) the first iterate's
    // membrane strain, quadratic in the deflection, gives a residual far above the load, which a
    // backtracking line search answers with ever shorter steps (measured on the plate's 4 x 32
    // cells: 25 iterations, each cutting the residual by 5 to 10 %, and the first step cut to 1e-6
    // of Pmax). A full step that diverges is cut back by the stepper instead.
    settings.newton.line_search = LineSearch::basic;
    // Plain Newton: a new factorisation at every iteration.
    settings.newton.reuse_factor = false;
    // Steps of 5 or more iterations are common along these paths (measured); they should not
    // shrink the next one.
    settings.easy_iterations = 10;
    settings.newton.max_iterations = 40;
    LoadStepper stepper(model, settings);
    if (reached) stepper.resume(*reached);
    const SteppingResult result = stepper.run([](const StepInfo&) {}, [](const std::string&) {});
    if (!result.completed) {
      ADD_FAILURE() << "P/Pmax = " << level << " not reached: " << result.failure;
      return curve;
    }
    reached = stepper.state();
    curve.steps = reached->steps;
    curve.values.push_back(read(model.state()));
  }
  for (const shell::ShellOutputs& element : model.shell_outputs())
    for (const Vec3d& stretches : element.face_stretches)
      for (int k = 0; k < 3; ++k)
        curve.largest_strain = std::max(curve.largest_strain, std::abs(stretches[k] - 1.0));
  curve.completed = true;
  curve.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return curve;
}

// Slit annular plate under a lifting line force (Sze et al. 2004, section 3.3; Başar & Ding 1992):
// the annulus Ri = 6 <= r <= Ro = 10 in z = 0, t = 0.03, E = 2.1e7, ν = 0, slit along θ = 0; the
// side θ = 2π clamped, the side θ = 0 lifted by the dead line force q along +z, Pmax = 0.8 per unit
// length (3.2 in all). w_A and w_B: the lift of the loaded side at r = Ri and r = Ro. Meshes:
// n_r x n_θ cells (radial x around), cut along one diagonal.
constexpr double kPlateInner = 6.0, kPlateOuter = 10.0, kPlateThickness = 0.03;
constexpr double kPlateLineForce = 0.8;
const Elastic kPlateMaterial{2.1e7, 0.0};
// Sze et al. 2004, table of section 3.3 (their S4R, 10 x 80 elements), as MBDyn's test suite
// transcribes it: P/Pmax, w_A, w_B.
const Table kPlateTable = {{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0},
                           {{4.277, 5.876},
                            {6.725, 9.160},
                            {8.340, 11.213},
                            {9.529, 12.661},
                            {10.468, 13.768},
                            {11.257, 14.674},
                            {11.970, 15.469},
                            {12.642, 16.202},
                            {13.282, 16.886},
                            {13.891, 17.528}}};

Curve slit_annular_plate(int n_r, int n_theta, Model model, double max_step) {
  Mesh mesh = mapped_surface(
      n_r, n_theta,
      [](double s, double r) {
        const double radius = kPlateInner + s * (kPlateOuter - kPlateInner), theta = 2.0 * kPi * r;
        return Vec3d(radius * std::cos(theta), radius * std::sin(theta), 0.0);
      },
      kPlateThickness);
  const auto node = [n_theta](int i, int j) { return i * (n_theta + 1) + j; };
  ConstraintSet set;
  prescribe_surface(mesh, SurfaceRef{"r1", {}}, {0.0, 0.0, 0.0}, Ramp{}, set);  // θ = 2π
  clamp_sides(mesh, mesh.edge_tags.at("r1"));
  // The line force's consistent nodal forces on the straight side θ = 0: q h per inner node, half
  // at its ends.
  const double h = (kPlateOuter - kPlateInner) / n_r;
  std::vector<NodalForce> forces;
  for (int i = 0; i <= n_r; ++i)
    forces.push_back(
        {node(i, 0), Vec3d(0.0, 0.0, kPlateLineForce * h * (i == 0 || i == n_r ? 0.5 : 1.0))});
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<DeadLoad>("q", std::move(forces), Ramp{}));
  const int a = node(0, 0), b = node(n_r, 0);
  return follow_path(
      mesh, material_of(kPlateMaterial, model), kPlateMaterial.inverse_bulk_modulus(),
      set.components(), std::move(terms), kPlateTable.levels, max_step,
      1e-8 * kPlateLineForce * (kPlateOuter - kPlateInner), [a, b](const std::vector<double>& x) {
        return std::vector<double>{x[DofMap::dof(a, 2)], x[DofMap::dof(b, 2)]};
      });
}

// Hemisphere with an 18° hole under alternating radial forces (Sze et al. 2004, section 3.4;
// the geometry and material of the linear obstacle course, shell_fixtures.hpp): four radial
// point forces P on the equator, outward at ±x and inward at ±y, Pmax = 400; the quarter
// x, y >= 0 with symmetry at x = 0 and y = 0 carries P/2 at (R, 0, 0) along +x and at (0, R, 0)
// along -y, and z is held at the hole's node on y = 0 (its reaction is zero: the loads balance).
// Read: the outward displacement of the pulled point and the inward one of the pushed point.
constexpr double kSphereLoad = 400.0;
// Sze et al. 2004, table of section 3.4, as Elmer's open-hemisphere shell test transcribes it:
// P/Pmax, then the smaller and the larger displacement (see the top of this file).
const Table kSphereTable = {{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0},
                            {{1.499, 1.840},
                             {2.321, 3.261},
                             {2.819, 4.339},
                             {3.158, 5.196},
                             {3.406, 5.902},
                             {3.598, 6.497},
                             {3.750, 7.006},
                             {3.875, 7.448},
                             {3.979, 7.835},
                             {4.067, 8.178}}};

Curve pinched_hemisphere(int n, Model model, double max_step) {
  using namespace shell_test::hemisphere;
  Mesh mesh = shell_test::hemisphere_mesh(n);
  const auto node = [n](int i, int j) { return i * (n + 1) + j; };
  ConstraintSet set;
  symmetry(mesh, "s0", set);            // y = 0
  symmetry(mesh, "s1", set);            // x = 0
  set.add(node(0, 0), 2, 0.0, Ramp{});  // the hole's node on y = 0
  const int on_x = node(0, n), on_y = node(n, n);
  const double f = kSphereLoad / 2.0;
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<DeadLoad>(
      "F", std::vector<NodalForce>{{on_x, Vec3d(f, 0.0, 0.0)}, {on_y, Vec3d(0.0, -f, 0.0)}},
      Ramp{}));
  return follow_path(
      mesh, material_of(kMaterial, model), kMaterial.inverse_bulk_modulus(), set.components(),
      std::move(terms), kSphereTable.levels, max_step, 1e-8 * kSphereLoad,
      [on_x, on_y](const std::vector<double>& x) {
        return std::vector<double>{x[DofMap::dof(on_x, 0)], -x[DofMap::dof(on_y, 1)]};
      });
}

// Pull-out of an open-ended cylinder (Sze et al. 2004, section 3.5; Jiang & Chernuka 1994): R =
// 4.953, L = 10.35, t = 0.094, E = 1.05e7, ν = 0.3125, both ends free, pulled apart at mid-length
// by two opposite radial forces P, Pmax = 40000. The octant x in [0, L/2], θ in [0, 90°]
// ((x, R cos θ, R sin θ)) with symmetry at x = 0, z = 0 and y = 0 carries P/4 at (0, 0, R) along
// +z. Read: w_A, the outward displacement under the load, and -u_B, -u_C, the inward ones at
// (0, R, 0) (mid-length) and (L/2, R, 0) (free edge). Meshes: n_x x n_θ cells.
constexpr double kPullRadius = 4.953, kPullLength = 10.35, kPullThickness = 0.094;
constexpr double kPullLoad = 40000.0;
const Elastic kPullMaterial{1.05e7, 0.3125};
// Sze et al. 2004, table of section 3.5 (their S4R, 24 x 36 elements on the octant), as MBDyn's
// test suite transcribes it: P/Pmax, w_A, -u_B, -u_C.
const Table kPullTable = {{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0},
                          {{1.707, 2.217, 2.293},
                           {2.079, 2.904, 3.106},
                           {2.257, 3.227, 3.452},
                           {2.376, 3.443, 3.632},
                           {2.473, 3.653, 3.718},
                           {2.618, 4.274, 3.452},
                           {2.672, 4.385, 3.378},
                           {2.710, 4.455, 3.332},
                           {2.741, 4.508, 3.297},
                           {2.768, 4.551, 3.269}}};

Curve pulled_cylinder(int n_x, int n_theta, Model model, double max_step) {
  Mesh mesh = mapped_surface(
      n_x, n_theta,
      [](double s, double r) {
        const double theta = r * kPi / 2.0;
        return Vec3d(s * kPullLength / 2.0, kPullRadius * std::cos(theta),
                     kPullRadius * std::sin(theta));
      },
      kPullThickness);
  const auto node = [n_theta](int i, int j) { return i * (n_theta + 1) + j; };
  ConstraintSet set;
  symmetry(mesh, "s0", set);  // x = 0
  symmetry(mesh, "r0", set);  // z = 0
  symmetry(mesh, "r1", set);  // y = 0
  const int a = node(0, n_theta), b = node(0, 0), c = node(n_x, 0);
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<DeadLoad>(
      "P", std::vector<NodalForce>{{a, Vec3d(0.0, 0.0, kPullLoad / 4.0)}}, Ramp{}));
  return follow_path(mesh, material_of(kPullMaterial, model), kPullMaterial.inverse_bulk_modulus(),
                     set.components(), std::move(terms), kPullTable.levels, max_step,
                     1e-8 * kPullLoad, [a, b, c](const std::vector<double>& x) {
                       return std::vector<double>{x[DofMap::dof(a, 2)], -x[DofMap::dof(b, 1)],
                                                  -x[DofMap::dof(c, 1)]};
                     });
}

/// Prints `curve` against `table` and returns, per level, the largest relative error of its
/// displacements.
std::vector<double> compare(const char* what, const Curve& curve, const Table& table) {
  std::vector<double> errors;
  std::printf("%s (%d nodes, %d steps, %.1f s, largest strain %.2e):\n", what, curve.nodes,
              curve.steps, curve.seconds, curve.largest_strain);
  for (std::size_t k = 0; k < curve.values.size(); ++k) {
    double error = 0.0;
    std::printf("  P/Pmax %.2f:", table.levels[k]);
    for (std::size_t c = 0; c < curve.values[k].size(); ++c) {
      const double e = curve.values[k][c] / table.values[k][c] - 1.0;
      error = std::max(error, std::abs(e));
      std::printf(" %.4f (%.3f, %+.2e)", curve.values[k][c], table.values[k][c], e);
    }
    std::printf("\n");
    errors.push_back(error);
  }
  return errors;
}

/// The largest relative difference between the displacements of two curves at any level.
double largest_difference(const Curve& a, const Curve& b) {
  double largest = 0.0;
  for (std::size_t k = 0; k < std::min(a.values.size(), b.values.size()); ++k)
    for (std::size_t c = 0; c < a.values[k].size(); ++c)
      largest = std::max(largest, std::abs(b.values[k][c] / a.values[k][c] - 1.0));
  return largest;
}

/// What every benchmark asserts: both meshes reach Pmax; on the finer mesh every displacement at
/// every level of the table from `first_level` on within 2 % of Sze et al.'s (and below
/// `early_bound` before it); at no level the finer mesh farther from the table than the coarser
/// by more than kMargin, and the coarser within `coarse_bound` at every level; the Mooney–Rivlin on
/// the coarser mesh within `material_bound` of the neo-Hookean there, and the largest strain of
/// the finer mesh under `strain_bound`.
void expect_benchmark(const char* what, const Table& table, const Curve& coarse, const Curve& fine,
                      const Curve& coarse_mooney_rivlin, double coarse_bound, double material_bound,
                      double strain_bound, double first_level = 0.0, double early_bound = 2e-2) {
  ASSERT_TRUE(coarse.completed && fine.completed && coarse_mooney_rivlin.completed) << what;
  const std::string name = what;
  const std::vector<double> coarse_errors = compare((name + ", coarser").c_str(), coarse, table);
  const std::vector<double> fine_errors = compare((name + ", finer").c_str(), fine, table);
  const double material = largest_difference(coarse, coarse_mooney_rivlin);
  std::printf(
      "%s: largest error %.2e (coarser), %.2e (finer); Mooney-Rivlin against neo-Hookean "
      "%.2e; largest strain %.2e (coarser), %.2e (finer)\n",
      what, *std::max_element(coarse_errors.begin(), coarse_errors.end()),
      *std::max_element(fine_errors.begin(), fine_errors.end()), material, coarse.largest_strain,
      fine.largest_strain);
  for (std::size_t k = 0; k < table.levels.size(); ++k) {
    const double bound = table.levels[k] < first_level - 1e-12 ? early_bound : 2e-2;
    EXPECT_LT(fine_errors[k], bound) << what << ", P/Pmax = " << table.levels[k];
    EXPECT_LT(fine_errors[k], coarse_errors[k] + kMargin)
        << what << ", P/Pmax = " << table.levels[k];
    EXPECT_LT(coarse_errors[k], coarse_bound) << what << ", P/Pmax = " << table.levels[k];
  }
  EXPECT_LT(material, material_bound) << what;
  EXPECT_LT(fine.largest_strain, strain_bound) << what;
}

// The plate on 4 x 64 and 8 x 128 cells (radial x around: cells about 1.3 times as long across as
// around; see the next test for cells of other shapes). Measured: largest errors 1.64e-2 and
// 1.22e-2, both at P/Pmax = 0.1 and below the table, falling along the path to 6.3e-4 and 2.1e-3
// at Pmax (from P/Pmax = 0.5 on the finer mesh is the farther, by at most 2.7e-3); Mooney–Rivlin
// against neo-Hookean 4.0e-6; largest strain 2.2e-3 and 3.0e-3.
TEST(ShellSze, SlitAnnularPlateFollowsTheTable) {
  expect_benchmark("slit annular plate", kPlateTable,
                   slit_annular_plate(4, 64, Model::neo_hookean, kMaxStep),
                   slit_annular_plate(8, 128, Model::neo_hookean, kMaxStep),
                   slit_annular_plate(4, 64, Model::mooney_rivlin, kMaxStep), 2.5e-2, 1e-4, 1e-2);
}

// Where the element is weakest: cells longer around the plate than across it come out too stiff,
// and refining across alone makes it worse. At P/Pmax = 0.1, 8 x 64 cells (0.5 across, 0.79
// around at r = 8) are 4.9e-2 below the table and 16 x 64 (0.25 across) 9.3e-2 below, against
// 1.6e-2 on 4 x 64 and 1.2e-2 on 8 x 128 (the test above); measured also: 16 x 128, 2.7e-2.
TEST(ShellSze, SlitAnnularPlateIsTooStiffOnCellsLongerAroundThanAcross) {
  const Curve across_8 = slit_annular_plate(8, 64, Model::neo_hookean, kMaxStep);
  const Curve across_16 = slit_annular_plate(16, 64, Model::neo_hookean, kMaxStep);
  ASSERT_TRUE(across_8.completed && across_16.completed);
  const double error_8 = compare("slit annular plate, 8 x 64", across_8, kPlateTable).front();
  const double error_16 = compare("slit annular plate, 16 x 64", across_16, kPlateTable).front();
  for (const Curve* curve : {&across_8, &across_16})
    EXPECT_LT(curve->values.front()[0], kPlateTable.values.front()[0]);  // too stiff: below
  EXPECT_GT(error_8, 3e-2);
  EXPECT_GT(error_16, 1.5 * error_8);
}

// The quarter hemisphere on 32 x 32 and 64 x 64 cells. Measured: largest errors 3.03e-2
// and 2.02e-2, both of the pushed point at P/Pmax = 0.1, below the table; from 0.2 on the finer
// mesh within 1.56e-2 (2.7e-3 and 4.7e-3 at Pmax). The 2 % hold from P/Pmax = 0.2 on; at 0.1 the
// bound is 2.5 %, and the error there falls only 1.5-fold per halving (shell.md, section 9).
// Mooney–Rivlin against neo-Hookean 9.7e-6; largest strain 1.7e-2 and 2.3e-2, at the point loads.
TEST(ShellSze, HemisphereFollowsTheTable) {
  expect_benchmark("hemisphere", kSphereTable, pinched_hemisphere(32, Model::neo_hookean, kMaxStep),
                   pinched_hemisphere(64, Model::neo_hookean, kMaxStep),
                   pinched_hemisphere(32, Model::mooney_rivlin, kMaxStep), 4e-2, 1e-4, 5e-2, 0.2,
                   2.5e-2);
}

// The cylinder's octant on 16 x 24 and 32 x 48 cells (along x around). Measured: largest errors
// 2.23e-2 (-u_B at P/Pmax = 0.6) and 8.6e-3 (-u_B at Pmax), above the table. The largest strain,
// 0.18 and 0.29, is at the point load, where it grows as the cells shrink; the Mooney–Rivlin
// changes the displacements by 5.5e-3 at most: under the 2 %, though not negligible beside the
// finer mesh's error.
TEST(ShellSze, PulledCylinderFollowsTheTable) {
  expect_benchmark("pulled cylinder", kPullTable,
                   pulled_cylinder(16, 24, Model::neo_hookean, kMaxStep),
                   pulled_cylinder(32, 48, Model::neo_hookean, kMaxStep),
                   pulled_cylinder(16, 24, Model::mooney_rivlin, kMaxStep), 3e-2, 1e-2, 0.5);
}

}  // namespace
}  // namespace plisse
