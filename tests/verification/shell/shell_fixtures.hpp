#pragma once
/// What the shell's verification tests share: the strip of edge_conditions_test.cpp and
/// euler_strip_test.cpp, cut three ways; the pseudo-random numbers that distort meshes the same
/// way on every platform; and the solve of a flat shell under a small pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "mesh/shell_surface.hpp"
#include "physics/dirichlet.hpp"
#include "physics/pressure_load.hpp"
#include "solver/load_stepper.hpp"
#include "solver/mixed_model.hpp"

namespace plisse::shell_test {

/// A number in [-1, 1] that depends only on (i, j, which): a distortion is the same on every
/// platform (std:: distributions are not).
inline double pseudo_random(int i, int j, int which) {
  std::uint64_t z = 0x9E3779B97F4A7C15ULL *
                    static_cast<std::uint64_t>(i * 7919 + j * 104729 + which * 15485863 + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return 2.0 * static_cast<double>(z >> 11) / static_cast<double>(1ULL << 53) - 1.0;
}

/// The strip of edge_conditions_test.cpp, euler_strip_test.cpp and gravity_test.cpp: L x W x t,
/// an incompressible neo-Hookean sheet (W = c1 (I1 - 3), μ = 2 c1) that bends in plane strain with
/// the rigidity D = μ t³/3 per unit width (E = 3 μ, ν = 1/2; docs/theory/shell.md, KL13).
namespace strip_constants {
constexpr double kC1 = 0.5;         // [MPa]: μ = 1 MPa
constexpr double kLength = 100.0;   // L [mm]
constexpr double kWidth = 10.0;     // W [mm]
constexpr double kThickness = 1.0;  // t [mm]
constexpr double kRigidity = 2.0 * kC1 * kThickness * kThickness * kThickness / 3.0;  // D [N mm]
}  // namespace strip_constants

/// How the strip's cells are cut: all along the diagonal from (x, y) to (x + h, y + h); along
/// alternating diagonals (cell (i, j) along the other one when i + j is odd); or alternating with
/// every node off the strip's edges moved in the plane by up to 15 % of the cell's sides (the
/// nodes at x = keep_x only across the strip, so that a deflection can be read there).
enum class Cells { same_diagonal, alternating, distorted };

/// The strip [0, length] x [0, width] in z = 0 of reference thickness `thickness`, nx x ny cells
/// each cut into two triangles as `cells` says, normals +z. Edge tags `left` (x = 0), `right`
/// (x = length), `front` (y = 0), `back` (y = width); surface tag `bottom` (the -1 face: a
/// pressure on it pushes along +z).
inline Mesh strip_mesh(double length, double width, double thickness, int nx, int ny, Cells cells,
                       double keep_x) {
  Mesh mesh;
  const auto node = [&](int i, int j) { return i * (ny + 1) + j; };
  const double hx = length / nx, hy = width / ny;
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      Vec3d X(hx * i, hy * j, 0.0);
      const bool inner = i > 0 && i < nx && j > 0 && j < ny;
      if (cells == Cells::distorted && inner) {
        if (std::abs(X.x() - keep_x) > 1e-9) X.x() += 0.15 * hx * pseudo_random(i, j, 0);
        X.y() += 0.15 * hy * pseudo_random(i, j, 1);
      }
      mesh.nodes.push_back(X);
    }
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      if (cells == Cells::same_diagonal || (i + j) % 2 == 0) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else {
        mesh.triangles.push_back({a, b, d});
        mesh.triangles.push_back({b, c, d});
      }
    }
  for (int k = 0; k < static_cast<int>(mesh.triangles.size()); ++k)
    mesh.surface_tags["bottom"].push_back(k);
  const auto add_edge = [&](const std::string& tag, int a, int b) {
    mesh.edge_tags[tag].push_back(static_cast<int>(mesh.edges.size()));
    mesh.edges.push_back({a, b});
  };
  for (int j = 0; j < ny; ++j) {
    add_edge("left", node(0, j), node(0, j + 1));
    add_edge("right", node(nx, j), node(nx, j + 1));
  }
  for (int i = 0; i < nx; ++i) {
    add_edge("front", node(i, 0), node(i + 1, 0));
    add_edge("back", node(i, ny), node(i + 1, ny));
  }
  make_shell_surface(mesh, thickness);
  return mesh;
}

/// The strip's long edges `front` (y = 0) and `back` (y = width) as symmetry edges: v = 0 and
/// their sides mirrored (KL8a), plane strain in y.
inline void symmetric_long_edges(Mesh& mesh, double width, ConstraintSet& set) {
  hold_in_plane(mesh, SurfaceRef{"front", {}}, set);
  hold_in_plane(mesh, SurfaceRef{"back", {}}, set);
  mirror_sides(mesh, mesh.edge_tags.at("front"), 1, 0.0);
  mirror_sides(mesh, mesh.edge_tags.at("back"), 1, width);
}

/// Solves `model` (its loads ramped over [0, 1]) in one load step, Newton stopping at the
/// residual `atol` [N] or `rtol` of the first. Fails the calling test when the step does not
/// converge; returns whether it did.
inline bool solve_in_one_step(MixedModel& model, double atol, double rtol = 1e-8) {
  SteppingSettings settings;
  settings.steps = 1;
  settings.max_step = 1.0;
  settings.newton.rtol = rtol;
  settings.newton.atol = atol;
  LoadStepper stepper(model, settings);
  const SteppingResult result = stepper.run([](const StepInfo&) {}, [](const std::string&) {});
  EXPECT_TRUE(result.completed) << result.failure;
  return result.completed;
}

/// The state of the neo-Hookean shell `mesh` (c1 [MPa]) held by `constraints` under the pressure
/// q [MPa] on its `bottom` face, in one load step. Newton stops at 1e-13 N: under these loads
/// (nodal forces 1e-9 to 1e-6 N) the residual falls to its round-off, 1e-14 to 3e-14 N (SNES's
/// monitor), in two iterations; or at `rtol` of the first residual, for larger forces. Fails the
/// calling test when the step does not converge.
inline std::vector<double> solve_under_pressure(
    const Mesh& mesh, const std::vector<ConstrainedComponent>& constraints, double c1, double q,
    double rtol = 1e-8) {
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<PressureLoad>(mesh, "q", "bottom", q, Ramp{}, constraints, 0));
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", c1}}), 0.0, constraints,
                   std::move(terms), ElementFamily::shell);
  solve_in_one_step(model, 1e-13, rtol);
  return model.state();
}

}  // namespace plisse::shell_test
