// The linear shell obstacle course (MacNeal & Harder 1985, "A proposed standard set of problems to
// test finite element accuracy", Finite Elements in Analysis and Design 1; Belytschko, Stolarski,
// Liu, Carpenter & Ong 1985, "Stress projection for membrane and shear locking in shell finite
// elements", CMAME 51) on the rotation-free shell triangle (docs/theory/shell.md): the Scordelis–Lo
// roof, the pinched cylinder with end diaphragms and the pinched hemisphere with an 18° hole, each
// on a symmetric part with `symmetry` edges (KL8a), against the references of those papers.
//
// Linear answers from a finite-strain code. The references are linear (small-displacement)
// answers; at their full loads the roof and the hemisphere deflect by more than their thickness
// (w/t = 1.2 and 2.3), where the geometric nonlinearity would change w by tens of percent. Their
// loads are therefore scaled by 1e-4 and the displacements scaled back: the nonlinearity then
// changes w by O(1e-4) of itself. The first Newton iterate from the reference state is the linear
// answer itself; the next ones add the nonlinearity. The pinched cylinder keeps its load
// (w/t = 6e-6: already linear): the round-off of its residual, about 7e-7 at E t = 9e6, would be
// 3 % of 1e-4 of its load and blurs the answer at that scale, and Newton cannot converge below it.
// Materials. The references are linear isotropic (E, ν). plisse's models are isochoric, with a
// bulk modulus κ for the volume (shell.md, KL12): the neo-Hookean W = c1 (Ī1 - 3) with
//   μ = E / (2 (1 + ν)),   c1 = μ / 2,   κ = E / (3 (1 - 2 ν))
// is at small strain linear elasticity with E and ν, and its plane-stress shell is the
// Kirchhoff–Love shell of the references (membrane rigidity E t/(1 - ν²), bending E t³/(12 (1 -
// ν²))).
//
// Meshes. Each part is a structured grid of n x n cells on its parameters (axial position and
// angle), each cell cut along the diagonal from (i, j) to (i + 1, j + 1), as the strips of
// edge_conditions_test.cpp; the nodes lie on the exact surface. The pinched cylinder is also
// meshed with cells graded towards its point load.
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
#include <tuple>
#include <utility>
#include <vector>

#include "material/registry.hpp"
#include "mesh/shell_surface.hpp"
#include "physics/body_force.hpp"
#include "physics/dead_load.hpp"
#include "physics/dirichlet.hpp"
#include "shell_fixtures.hpp"
#include "solver/mixed_model.hpp"
#include "support/extrapolation.hpp"

namespace plisse {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
/// The factor on the loads of the roof and the hemisphere (see above); their displacements are
/// divided by it.
constexpr double kLoadScale = 1e-4;

using namespace shell_test;

/// A rigid diaphragm on the edge tag in the plane x_axis = const: the two displacement components
/// in its plane held, the one along `axis` free, the side free to turn (KL8).
void diaphragm(const Mesh& mesh, const std::string& tag, int axis, ConstraintSet& set) {
  std::array<std::optional<double>, 3> held = {0.0, 0.0, 0.0};
  held[static_cast<std::size_t>(axis)].reset();
  prescribe_surface(mesh, SurfaceRef{tag, {}}, held, Ramp{}, set);
}

/// What one solve gives: the displacement the reference quotes, scaled back by kLoadScale, and
/// the seconds it took.
struct Answer {
  double displacement = 0.0;
  double seconds = 0.0;
  int nodes = 0;
};

/// Solves the part `mesh` with `constraints` under `terms` in one load step and returns the state.
/// Newton stops at `atol` [N] (set well above the round-off of the residual, well below the load).
std::vector<double> solve(const Mesh& mesh, const Elastic& material,
                          const std::vector<ConstrainedComponent>& constraints,
                          std::vector<std::unique_ptr<ModelTerm>> terms, double atol) {
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", material.c1()}}),
                   material.inverse_bulk_modulus(), constraints, std::move(terms),
                   ElementFamily::shell);
  shell_test::solve_in_one_step(model, atol);
  return model.state();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Scordelis–Lo roof (MacNeal & Harder 1985, figure 5; Belytschko et al. 1985): a cylindrical roof
// of radius 25 and length 50 along x, spanning ±40° about the vertical, t = 0.25, E = 4.32e8,
// ν = 0, under its weight of 90 per unit area (ρ g t = 90) along -z; its ends x = 0 and x = 50
// rest on rigid diaphragms (u_y = u_z = 0), its long edges are free. The quarter x in [0, 25],
// θ in [0, 40°] (θ from the crown), with symmetry at x = 25 and at the crown y = 0. Reference:
// the vertical deflection of the free edge at mid-span, 0.3024 (Belytschko et al. 1985; MacNeal &
// Harder quote 0.3086 of deep-shell theory).
constexpr double kRoofRadius = 25.0, kRoofLength = 50.0, kRoofAngle = 40.0 * kDegree;
constexpr double kRoofThickness = 0.25;
constexpr double kRoofWeight = 90.0;  // per unit area
constexpr double kRoofReference = 0.3024;
const Elastic kRoofMaterial{4.32e8, 0.0};

Mesh roof_mesh(int n) {
  return mapped_surface(
      n, n,
      [](double s, double r) {
        const double theta = r * kRoofAngle;
        return Vec3d(s * kRoofLength / 2.0, kRoofRadius * std::sin(theta),
                     kRoofRadius * std::cos(theta));
      },
      kRoofThickness);
}

/// The roof's quarter on n x n cells: -u_z at the free edge's mid-span node.
Answer scordelis_lo_roof(int n, const Elastic& material = kRoofMaterial) {
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh = roof_mesh(n);
  ConstraintSet set;
  diaphragm(mesh, "s0", 0, set);  // x = 0
  symmetry(mesh, "s1", set);      // x = L/2
  symmetry(mesh, "r0", set);      // the crown, y = 0
  std::vector<std::unique_ptr<ModelTerm>> terms;
  const double force_density = kLoadScale * kRoofWeight / kRoofThickness;  // ρ g
  terms.push_back(std::make_unique<BodyForce>(mesh, "g", Vec3d(0.0, 0.0, -force_density), Ramp{}));
  const int probe = node_at(mesh, Vec3d(kRoofLength / 2.0, kRoofRadius * std::sin(kRoofAngle),
                                        kRoofRadius * std::cos(kRoofAngle)));
  EXPECT_GE(probe, 0);
  // The quarter's weight is 90 x 25 x 25 x 40° = 3.9e4, 3.9 at the scaled load; 1e-6 of it.
  const std::vector<double> state = solve(mesh, material, set.components(), std::move(terms), 4e-6);
  return {-state[DofMap::dof(probe, 2)] / kLoadScale, seconds_since(start), mesh.n_nodes()};
}

// Pinched cylinder with end diaphragms (MacNeal & Harder 1985, figure 8; Belytschko et al. 1985):
// radius 300, length 600 along x, t = 3, E = 3e6, ν = 0.3, pinched at mid-length by two opposite
// radial point loads P = 1; the ends x = ±300 on rigid diaphragms. The octant x in [0, 300],
// θ in [0, 90°] (from the top, (x, R sin θ, R cos θ)), with symmetry at x = 0, y = 0 and z = 0,
// loaded by P/4 on its corner (0, 0, R) along -z. Reference: the radial displacement under the
// load, 1.8248e-5 (Belytschko et al. 1985).
constexpr double kCylinderRadius = 300.0, kCylinderLength = 600.0, kCylinderThickness = 3.0;
constexpr double kCylinderLoad = 1.0;
constexpr double kCylinderReference = 1.8248e-5;
const Elastic kCylinderMaterial{3e6, 0.3};
/// The grading of the cylinder's cells towards the load (mapped_surface).
constexpr double kCylinderGrading = 1.5;

/// The octant on n x n cells; `grading` > 1 makes them finer towards the loaded corner (s = r = 0).
Mesh cylinder_mesh(int n, double grading = 1.0) {
  return mapped_surface(
      n, n,
      [](double s, double r) {
        const double theta = r * kPi / 2.0;
        return Vec3d(s * kCylinderLength / 2.0, kCylinderRadius * std::sin(theta),
                     kCylinderRadius * std::cos(theta));
      },
      kCylinderThickness, grading);
}

/// The cylinder's octant on n x n cells: the inward radial displacement under the load.
Answer pinched_cylinder(int n, double grading = 1.0, const Elastic& material = kCylinderMaterial) {
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh = cylinder_mesh(n, grading);
  ConstraintSet set;
  symmetry(mesh, "s0", set);      // x = 0
  diaphragm(mesh, "s1", 0, set);  // x = L/2
  symmetry(mesh, "r0", set);      // y = 0
  symmetry(mesh, "r1", set);      // z = 0
  const int loaded = node_at(mesh, Vec3d(0.0, 0.0, kCylinderRadius));
  EXPECT_GE(loaded, 0);
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<DeadLoad>(
      "P", std::vector<NodalForce>{{loaded, Vec3d(0.0, 0.0, -kCylinderLoad / 4.0)}}, Ramp{}));
  // The load is 0.25 (unscaled, see above); 1e-5 of it, above the residual's round-off.
  const std::vector<double> state =
      solve(mesh, material, set.components(), std::move(terms), 2.5e-6);
  return {-state[DofMap::dof(loaded, 2)], seconds_since(start), mesh.n_nodes()};
}

// Pinched hemisphere with an 18° hole (MacNeal & Harder 1985, figure 9; Belytschko et al. 1985):
// radius 10, t = 0.04, E = 6.825e7, ν = 0.3, the hemisphere z >= 0 open at its pole by a hole of
// 18° about the z axis, four radial point loads of 2 on the equator, outward at ±x and inward at
// ±y; the hole's edge and the equator free. The quarter x, y >= 0 with symmetry at x = 0 and
// y = 0: a load of 1 at (R, 0, 0) along +x and one at (0, R, 0) along -y (half of each load lies
// on the quarter). The loads balance along z, where the quarter is otherwise free to move: z is
// held at the hole's node on y = 0, whose reaction is then zero. Reference: the radial
// displacement at a load point in the direction of its load, 0.0924 (Belytschko et al. 1985;
// MacNeal & Harder quote 0.094). By the symmetry of the loads (a quarter turn about z and a change
// of sign), both load points move by the same amount, outward at x and inward at y.
constexpr double kSphereRadius = hemisphere::kRadius, kHole = hemisphere::kHole;
constexpr double kSphereLoad = 2.0;
constexpr double kSphereReference = 0.0924;
const Elastic kSphereMaterial = hemisphere::kMaterial;

/// The hemisphere's quarter on n x n cells: the displacements of the two load points along their
/// loads (x outward, y inward), the first in Answer::displacement.
std::pair<Answer, double> pinched_hemisphere(int n, const Elastic& material = kSphereMaterial) {
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh = hemisphere_mesh(n);
  ConstraintSet set;
  symmetry(mesh, "s0", set);  // y = 0
  symmetry(mesh, "s1", set);  // x = 0
  const int pole = node_at(mesh, kSphereRadius * Vec3d(std::sin(kHole), 0.0, std::cos(kHole)));
  EXPECT_GE(pole, 0);
  set.add(pole, 2, 0.0, Ramp{});
  const int on_x = node_at(mesh, Vec3d(kSphereRadius, 0.0, 0.0));
  const int on_y = node_at(mesh, Vec3d(0.0, kSphereRadius, 0.0));
  EXPECT_GE(on_x, 0);
  EXPECT_GE(on_y, 0);
  const double f = kLoadScale * kSphereLoad / 2.0;
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<DeadLoad>(
      "F", std::vector<NodalForce>{{on_x, Vec3d(f, 0.0, 0.0)}, {on_y, Vec3d(0.0, -f, 0.0)}},
      Ramp{}));
  // The loads are 1e-4 at their scale; the residual's round-off is about 1e-8 (measured), so
  // Newton stops at 3e-8, which it reaches in its second iteration.
  const std::vector<double> state = solve(mesh, material, set.components(), std::move(terms), 3e-8);
  const Answer a{state[DofMap::dof(on_x, 0)] / kLoadScale, seconds_since(start), mesh.n_nodes()};
  return {a, -state[DofMap::dof(on_y, 1)] / kLoadScale};
}

/// The relative errors of `answers` against `reference`, printed with the observed orders (per
/// halving of the cells).
std::vector<double> errors_of(const char* what, const std::vector<int>& cells,
                              const std::vector<Answer>& answers, double reference) {
  std::vector<double> errors;
  for (std::size_t k = 0; k < answers.size(); ++k) {
    const Answer& a = answers[k];
    errors.push_back(std::abs(a.displacement / reference - 1.0));
    std::printf("%s, %2d x %2d cells (%5d nodes): %.6e, reference %.6e, ratio %.5f, error %.2e",
                what, cells[k], cells[k], a.nodes, a.displacement, reference,
                a.displacement / reference, errors.back());
    if (k > 0) std::printf(", order %.2f", std::log2(errors[k - 1] / errors[k]));
    std::printf(" (%.1f s)\n", a.seconds);
  }
  return errors;
}

/// The area of a shell mesh's triangles.
double area_of(const Mesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 *
            (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]).norm();
  return area;
}

/// The largest |X_axis - value| over the nodes of an edge tag.
double off_plane(const Mesh& mesh, const std::string& tag, int axis, double value) {
  double largest = 0.0;
  for (const int e : mesh.edge_tags.at(tag))
    for (const int v : mesh.edges[static_cast<std::size_t>(e)])
      largest = std::max(largest, std::abs(mesh.nodes[static_cast<std::size_t>(v)][axis] - value));
  return largest;
}

// The three parts as meshed: the inscribed triangles' area converges at second order to the
// surface's (a chord of an arc of angle α is short by α²/24), every edge tag lies in its plane and
// the symmetry edges are found in theirs (shell_edge_plane_axis), the load points are nodes.
TEST(ShellObstacleCourse, ThePartsAreMeshedOnTheirSurfacesWithTheirEdgesInTheirPlanes) {
  struct Part {
    const char* name;
    std::function<Mesh(int)> mesh;
    double area;                                                    // of the exact surface
    std::vector<std::tuple<std::string, int, double, bool>> edges;  // tag, axis, value, symmetry
  };
  const double roof_area = kRoofRadius * kRoofAngle * kRoofLength / 2.0;
  const double cylinder_area = kCylinderRadius * kPi / 2.0 * kCylinderLength / 2.0;
  const double sphere_area = kPi / 2.0 * kSphereRadius * kSphereRadius * std::cos(kHole);
  const std::vector<Part> parts = {
      {"roof",
       roof_mesh,
       roof_area,
       {{"s0", 0, 0.0, false}, {"s1", 0, kRoofLength / 2.0, true}, {"r0", 1, 0.0, true}}},
      {"cylinder",
       [](int n) { return cylinder_mesh(n); },
       cylinder_area,
       {{"s0", 0, 0.0, true},
        {"s1", 0, kCylinderLength / 2.0, false},
        {"r0", 1, 0.0, true},
        {"r1", 2, 0.0, true}}},
      {"graded cylinder",
       [](int n) { return cylinder_mesh(n, kCylinderGrading); },
       cylinder_area,
       {{"s0", 0, 0.0, true},
        {"s1", 0, kCylinderLength / 2.0, false},
        {"r0", 1, 0.0, true},
        {"r1", 2, 0.0, true}}},
      {"hemisphere",
       hemisphere_mesh,
       sphere_area,
       {{"s0", 1, 0.0, true}, {"s1", 0, 0.0, true}, {"r1", 2, 0.0, false}}}};
  for (const Part& part : parts) {
    std::vector<double> errors;
    for (const int n : {4, 8, 16, 32}) {
      const Mesh mesh = part.mesh(n);
      errors.push_back(1.0 - area_of(mesh) / part.area);
      std::printf("%s, %2d x %2d cells: area short by %.3e\n", part.name, n, n, errors.back());
      EXPECT_GT(errors.back(), 0.0) << part.name;  // inscribed
      for (const auto& [tag, axis, value, mirrored] : part.edges) {
        EXPECT_LT(off_plane(mesh, tag, axis, value), 1e-12 * (1.0 + std::abs(value)))
            << part.name << " " << tag;
        if (mirrored) {
          EXPECT_EQ(shell_edge_plane_axis(mesh, mesh.edge_tags.at(tag)), axis);
        }
      }
    }
    for (std::size_t k = 1; k < errors.size(); ++k)
      EXPECT_NEAR(errors[k - 1] / errors[k], 4.0, 0.1) << part.name << ", halving " << k;
  }
  // The probes and load points are nodes of every mesh.
  for (const int n : {4, 8, 16, 32}) {
    EXPECT_GE(node_at(roof_mesh(n), Vec3d(kRoofLength / 2.0, kRoofRadius * std::sin(kRoofAngle),
                                          kRoofRadius * std::cos(kRoofAngle))),
              0);
    EXPECT_GE(node_at(cylinder_mesh(n), Vec3d(0.0, 0.0, kCylinderRadius)), 0);
    EXPECT_GE(node_at(cylinder_mesh(n, kCylinderGrading), Vec3d(0.0, 0.0, kCylinderRadius)), 0);
    EXPECT_GE(node_at(hemisphere_mesh(n), Vec3d(kSphereRadius, 0.0, 0.0)), 0);
    EXPECT_GE(node_at(hemisphere_mesh(n), Vec3d(0.0, kSphereRadius, 0.0)), 0);
  }
}

// The conditions and loads make solvable models: with exact incompressibility (ν = 1/2, shell.md
// KL9) Newton converges on every mesh of the three parts, and the hemisphere's two load points,
// images of each other under a quarter turn, move alike. The references are for ν = 0 and 0.3, so
// the numbers (printed) are not compared with them. Measured
// at ν = 1/2: roof 0.2839, 0.2913, 0.2954, 0.2996 (4 to 32 cells); cylinder 1.391e-5, 1.948e-5,
// 1.774e-5, 1.672e-5 (8 to 64 cells); hemisphere 0.0447, 0.0948, 0.1019, 0.1043 (8 to 64 cells).
TEST(ShellObstacleCourse, EveryPartSolvesWhenExactlyIncompressible) {
  const std::vector<int> roof_cells = {4, 8, 16, 32};
  std::vector<Answer> roof;
  for (const int n : roof_cells)
    roof.push_back(scordelis_lo_roof(n, Elastic{kRoofMaterial.E, 0.5}));
  errors_of("roof, nu = 1/2", roof_cells, roof, kRoofReference);
  const std::vector<int> cylinder_cells = {8, 16, 32, 64};
  std::vector<Answer> cylinder;
  for (const int n : cylinder_cells)
    cylinder.push_back(pinched_cylinder(n, 1.0, Elastic{kCylinderMaterial.E, 0.5}));
  errors_of("cylinder, nu = 1/2", cylinder_cells, cylinder, kCylinderReference);
  const std::vector<int> sphere_cells = {8, 16, 32, 64};
  std::vector<Answer> sphere;
  std::vector<double> asymmetry;
  for (const int n : sphere_cells) {
    const auto [a, other] = pinched_hemisphere(n, Elastic{kSphereMaterial.E, 0.5});
    sphere.push_back(a);
    asymmetry.push_back(std::abs(other / a.displacement - 1.0));
    std::printf(
        "hemisphere, nu = 1/2, %2d x %2d cells: the load point on y moves %.6e (%.2e from x's)\n",
        n, n, other, asymmetry.back());
  }
  errors_of("hemisphere, nu = 1/2", sphere_cells, sphere, kSphereReference);
  // The mesh is not turned with the loads (its diagonals are mirrored about φ = 45°), so the two
  // agree to the discretisation error: measured 1.6e-2, 1.05e-2, 6.7e-3 from 16 x 16 cells on.
  EXPECT_LT(asymmetry.back(), 1e-2);
  EXPECT_LT(asymmetry[3], asymmetry[2]);
  EXPECT_LT(asymmetry[2], asymmetry[1]);
}

// The references, with the materials they were computed for (ν = 0 and 0.3 through the bulk
// modulus of shell.md, KL12). Each test asserts the error against the reference on its finest
// mesh and its fall at every refinement, and prints Aitken's estimate of the limit of the last
// three meshes.
void expect_falling(const std::vector<double>& errors, const char* what) {
  for (std::size_t k = 1; k < errors.size(); ++k)
    EXPECT_LT(errors[k], errors[k - 1]) << what << ", refinement " << k;
}

/// Aitken's Δ² estimate of the limit of `answers` from their last three (exact when the increments
/// fall by a constant factor per halving), printed with the increments and the distance from the
/// reference.
double aitken_limit(const char* what, const std::vector<Answer>& answers, double reference) {
  const std::size_t k = answers.size() - 1;
  const double d1 = answers[k - 1].displacement - answers[k - 2].displacement;
  const double d2 = answers[k].displacement - answers[k - 1].displacement;
  const test::Extrapolation fit = test::extrapolate_halvings(
      answers[k - 2].displacement, answers[k - 1].displacement, answers[k].displacement);
  std::printf(
      "%s: last increments %.3e, %.3e (ratio %.2f, order %.2f); Aitken's limit %.5e, %+.2e "
      "from the reference\n",
      what, d1, d2, d1 / d2, fit.order, fit.limit, fit.limit / reference - 1.0);
  return fit.limit;
}

// The roof at ν = 0 on 4² … 128² cells (8 s). Measured: errors 3.06e-2, 2.20e-2, 2.07e-2,
// 1.54e-2, 1.13e-2, 8.80e-3, from below, order 0.1 … 0.5: below 1 % only on 128². The increments
// fall by 1.66 per halving (order 0.73), and Aitken's limit is 0.3009, 5.0e-3 below the reference:
// the sequence converges slowly to a value half a percent under it (shell.md, section 9). The
// test holds the limit within 7e-3 of the reference, so that it fails if the rate or the limit
// drifts.
TEST(ShellObstacleCourse, ScordelisLoRoofConvergesToTheReference) {
  const std::vector<int> cells = {4, 8, 16, 32, 64, 128};
  std::vector<Answer> answers;
  for (const int n : cells) answers.push_back(scordelis_lo_roof(n));
  const std::vector<double> errors = errors_of("Scordelis-Lo roof", cells, answers, kRoofReference);
  EXPECT_LT(errors.back(), 1e-2);
  expect_falling(errors, "roof");
  const double limit = aitken_limit("Scordelis-Lo roof", answers, kRoofReference);
  EXPECT_LT(std::abs(limit / kRoofReference - 1.0), 7e-3);
}

// The pinched cylinder at ν = 0.3. On uniform cells, 8² … 128² (8 s), the error falls at order
// 1.0 … 1.5 from above (the point load's displacement converges more slowly than a smooth
// field's) and reaches 1.004e-2 on 128²: the test holds it under 1.05e-2 and the order of the
// last two halvings above 1.3 (measured 1.54, 1.52), and Aitken's limit of 32², 64², 128² within
// 1e-3 (measured +2.9e-4). On cells graded towards the load (grid lines at
// (i/n)^1.5, the first cell n^(-1/2) of a uniform one), 16² … 64² (3 s), it falls to 4.9e-3.
// Finer graded meshes leave the Newton tolerance below the residual's round-off: 128² graded, and
// a grading of 2 from 32², end in line-search failures (measured).

TEST(ShellObstacleCourse, PinchedCylinderConvergesToTheReference) {
  const std::vector<int> cells = {8, 16, 32, 64, 128};
  std::vector<Answer> answers;
  for (const int n : cells) answers.push_back(pinched_cylinder(n));
  const std::vector<double> errors =
      errors_of("pinched cylinder, uniform", cells, answers, kCylinderReference);
  EXPECT_LT(errors.back(), 1.05e-2);
  expect_falling(errors, "cylinder, uniform");
  for (std::size_t k = errors.size() - 2; k < errors.size(); ++k)
    EXPECT_GT(std::log2(errors[k - 1] / errors[k]), 1.3) << "uniform, refinement " << k;
  const double limit = aitken_limit("pinched cylinder, uniform", answers, kCylinderReference);
  EXPECT_LT(std::abs(limit / kCylinderReference - 1.0), 1e-3);

  const std::vector<int> graded_cells = {16, 32, 64};
  std::vector<Answer> graded;
  for (const int n : graded_cells) graded.push_back(pinched_cylinder(n, kCylinderGrading));
  const std::vector<double> graded_errors =
      errors_of("pinched cylinder, graded", graded_cells, graded, kCylinderReference);
  EXPECT_LT(graded_errors.back(), 1e-2);
  expect_falling(graded_errors, "cylinder, graded");
}

// The pinched hemisphere at ν = 0.3 on 8² … 128² cells (8 s). Measured: errors 5.1e-1 (8²: the
// flat facets lock), 7.0e-2, 2.1e-2, 4.8e-3 from below, then 3.4e-3 from above on 128²: the
// sequence crosses the reference between 64² and 128², and Aitken's limit of the last three is
// 1.2 % above it, towards MacNeal & Harder's 0.094. The test asserts the finest mesh within 1 %,
// the error falling, at order above 1.5 from 8² to 64² (measured 2.87, 1.75, 2.10), and the limit
// within 1.5 %.
TEST(ShellObstacleCourse, PinchedHemisphereConvergesToTheReference) {
  const std::vector<int> cells = {8, 16, 32, 64, 128};
  std::vector<Answer> answers;
  for (const int n : cells) answers.push_back(pinched_hemisphere(n).first);
  const std::vector<double> errors =
      errors_of("pinched hemisphere", cells, answers, kSphereReference);
  EXPECT_LT(errors.back(), 1e-2);
  expect_falling(errors, "hemisphere");
  for (std::size_t k = 1; k + 1 < errors.size(); ++k)
    EXPECT_GT(std::log2(errors[k - 1] / errors[k]), 1.5) << "refinement " << k;
  const double limit = aitken_limit("pinched hemisphere", answers, kSphereReference);
  EXPECT_LT(std::abs(limit / kSphereReference - 1.0), 1.5e-2);
}

}  // namespace
}  // namespace plisse
