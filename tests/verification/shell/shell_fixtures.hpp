#pragma once
/// What the shell's verification tests share: the strip of edge_conditions_test.cpp and
/// euler_strip_test.cpp, cut three ways; the pseudo-random numbers that distort meshes the same
/// way on every platform; the solve of a flat shell under a small pressure; the meshes on mapped
/// parameters, the elastic materials and the symmetry edges of obstacle_course_test.cpp and
/// sze_benchmarks_test.cpp, and their hemisphere with an 18° hole.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <numbers>
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

/// Linear isotropic elasticity (E, ν) as plisse's neo-Hookean W = c1 (Ī1 - 3) with a bulk
/// modulus κ (docs/theory/shell.md, KL12): μ = E / (2 (1 + ν)), c1 = μ / 2, κ = E / (3 (1 - 2 ν)),
/// linear elasticity with E and ν at small strain, whose plane-stress shell is the Kirchhoff–Love
/// shell with the membrane rigidity E t / (1 - ν²) and the bending rigidity E t³ / (12 (1 - ν²)).
struct Elastic {
  double E = 0.0;   ///< Young's modulus
  double nu = 0.0;  ///< Poisson's ratio, < 1/2 (1/2: exactly incompressible)
  double c1() const { return E / (4.0 * (1.0 + nu)); }
  double inverse_bulk_modulus() const { return 3.0 * (1.0 - 2.0 * nu) / E; }
};

/// The grid of n_s x n_r cells on the parameters (s, r) in [0, 1]², mapped onto the surface by
/// `map`, each cell cut along its diagonal from (s_i, r_j) to (s_i+1, r_j+1), normals along
/// X_s × X_r; thickness t. The grid lines are s_i = (i/n_s)^grading and r_j = (j/n_r)^grading:
/// uniform at 1, finer towards s = 0 and r = 0 above 1. Edge tags `s0`, `s1` (s = 0, 1: the sides
/// along r) and `r0`, `r1`.
inline Mesh mapped_surface(int n_s, int n_r, const std::function<Vec3d(double, double)>& map,
                           double thickness, double grading = 1.0) {
  Mesh mesh;
  const auto node = [&](int i, int j) { return i * (n_r + 1) + j; };
  const auto line = [grading](int i, int n) {
    return std::pow(static_cast<double>(i) / n, grading);
  };
  for (int i = 0; i <= n_s; ++i)
    for (int j = 0; j <= n_r; ++j) mesh.nodes.push_back(map(line(i, n_s), line(j, n_r)));
  for (int i = 0; i < n_s; ++i)
    for (int j = 0; j < n_r; ++j) {
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  const auto add_edge = [&](const std::string& tag, int a, int b) {
    mesh.edge_tags[tag].push_back(static_cast<int>(mesh.edges.size()));
    mesh.edges.push_back({a, b});
  };
  for (int j = 0; j < n_r; ++j) {
    add_edge("s0", node(0, j), node(0, j + 1));
    add_edge("s1", node(n_s, j), node(n_s, j + 1));
  }
  for (int i = 0; i < n_s; ++i) {
    add_edge("r0", node(i, 0), node(i + 1, 0));
    add_edge("r1", node(i, n_r), node(i + 1, n_r));
  }
  make_shell_surface(mesh, thickness);
  return mesh;
}

/// The node of `mesh` at X (within 1e-9 of its size), or -1.
inline int node_at(const Mesh& mesh, const Vec3d& X) {
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if ((mesh.nodes[v] - X).norm() < 1e-9 * (1.0 + X.norm())) return v;
  return -1;
}

/// `symmetry` on the edge tag: no displacement across its plane, the sides mirrored (KL8a).
inline void symmetry(Mesh& mesh, const std::string& tag, ConstraintSet& set) {
  const SurfaceRef ref{tag, {}};
  hold_in_plane(mesh, ref, set);
  const std::vector<int>& edges = mesh.edge_tags.at(tag);
  const int axis = shell_edge_plane_axis(mesh, edges);
  ASSERT_GE(axis, 0) << tag;
  mirror_sides(mesh, edges, axis,
               mesh.nodes[static_cast<std::size_t>(mesh.edges[edges[0]][0])][axis]);
}

/// The hemisphere of radius 10, t = 0.04, E = 6.825e7, ν = 0.3, open at its pole by a hole of 18°
/// about the z axis (MacNeal & Harder 1985, figure 9; Sze, Liu & Lo 2004, section 3.4): its
/// quarter x, y >= 0 on n x n cells, s the azimuth φ from the x axis (0 to 90°: edge `s0` on
/// y = 0, `s1` on x = 0), r the polar angle from the hole (`r0`) to the equator (`r1`, z = 0).
namespace hemisphere {
constexpr double kRadius = 10.0, kThickness = 0.04;
constexpr double kHole = 18.0 * std::numbers::pi / 180.0;  // [rad]
inline const Elastic kMaterial{6.825e7, 0.3};
}  // namespace hemisphere

inline Mesh hemisphere_mesh(int n) {
  using namespace hemisphere;
  constexpr double kPi = std::numbers::pi;
  return mapped_surface(
      n, n,
      [](double s, double r) {
        const double phi = s * kPi / 2.0, polar = kHole + r * (kPi / 2.0 - kHole);
        return Vec3d(kRadius * std::sin(polar) * std::cos(phi),
                     kRadius * std::sin(polar) * std::sin(phi), kRadius * std::cos(polar));
      },
      kThickness);
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
