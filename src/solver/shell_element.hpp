#pragma once
/// The rotation-free Kirchhoff-Love shell triangle (EBST, docs/theory/shell.md) as an element
/// policy of the assembly (solver/element_policy.hpp states the contract), on the mid-surface
/// of a shell mesh (mesh/shell_surface.hpp): 6 nodes, the triangle and the three nodes across
/// its sides (KL1), 18 unknowns [u0x, u0y, u0z, ..., u5z], no pressure unknowns and no internal
/// state.
///
/// A side without a neighbour (an edge of the surface) repeats the triangle's corner opposite
/// it in the node list (node 3 + i = node i): the node list keeps its fixed width, the geometry
/// reads the repetition as the missing neighbour (a free or hinged side, KL8), and the kernel's
/// rows and columns of that slot are zero, so its scatter onto the corner adds nothing.
///
/// The shell has no pressure unknown: the plane-stress condition eliminates the pressure inside
/// the kernel (KL9). The state keeps four values per node (solver/dof_map.hpp); the model
/// constrains the pressure value of every node of a shell to zero (solver/mixed_model.hpp), so
/// no equation is left without stiffness.
#include <array>
#include <span>

#include "element/element_fields.hpp"
#include "element/shell.hpp"
#include "element/shell_output.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "solver/dof_map.hpp"
#include "solver/element_policy.hpp"

namespace plisse {

struct ShellElement {
  static constexpr int kNodes = shell::kPatchNodes;
  static constexpr int kDof = shell::kPatchDofs;
  static constexpr int kInternalSize = 0;
  /// The points through the thickness (KL13): the section's rule has at most this many; a model
  /// with history keeps it at each (the kernel asks for the response at point q).
  static constexpr int kQuadPoints = shell::kMaxThicknessPoints;
  using Vector = shell::PatchVec;
  using Matrix = shell::PatchMat;
  using Fields = ElementFields;
  /// The patch's reference geometry and its cross-section (thickness and thickness points).
  struct Geometry {
    shell::ShellGeometry patch;
    shell::ShellSection section;
  };
  /// ok: the element could be evaluated; min_J: 1, every point is incompressible (KL9).
  struct Status {
    bool ok = true;
    double min_J = 1.0;
  };
  /// No internal state (kInternalSize = 0).
  struct Internal {
    double* data() { return nullptr; }
    const double* data() const { return nullptr; }
  };

  /// Local node (0..5) of unknown i: the components node by node.
  static constexpr std::array<int, kDof> kLocalNode = [] {
    std::array<int, kDof> node{};
    for (int i = 0; i < kDof; ++i) node[i] = i / 3;
    return node;
  }();

  /// The triangles of the shell mesh, each with the nodes across its sides
  /// (mesh.triangle_neighbours), a missing one replaced by the opposite corner. Precondition:
  /// mesh.is_shell().
  static int n_elements(const Mesh& mesh) { return static_cast<int>(mesh.triangles.size()); }
  static std::array<int, kNodes> nodes(const Mesh& mesh, int e) {
    const auto& corners = mesh.triangles[static_cast<std::size_t>(e)];
    const auto& across = mesh.triangle_neighbours[static_cast<std::size_t>(e)];
    std::array<int, kNodes> n;
    for (int i = 0; i < 3; ++i) {
      n[i] = corners[i];
      n[3 + i] = across[i] >= 0 ? across[i] : corners[i];
    }
    return n;
  }

  /// Full-state index of every element unknown: node a's (ux, uy, uz) at 3a..3a+2.
  static std::array<int, kDof> dofs(std::span<const int, kNodes> nodes) {
    std::array<int, kDof> full;
    for (int a = 0; a < kNodes; ++a)
      for (int k = 0; k < 3; ++k) full[3 * a + k] = DofMap::dof(nodes[a], k);
    return full;
  }

  /// shell::compute_shell_geometry of the patch, a repeated corner read as a missing neighbour,
  /// and the section of the element's thickness (the mean of its corners', mesh.shell_thickness)
  /// with the default points (KL13). Throws plisse::Error for a degenerate patch.
  static Geometry geometry(const Mesh& mesh, std::span<const int, kNodes> nodes) {
    shell::PatchPositions X;
    shell::NeighbourFlags has_neighbour;
    for (int a = 0; a < kNodes; ++a) X[a] = mesh.nodes[nodes[a]];
    for (int i = 0; i < 3; ++i) has_neighbour[i] = nodes[3 + i] != nodes[i];
    double thickness = 0.0;
    for (int i = 0; i < 3; ++i) thickness += mesh.shell_thickness[nodes[i]] / 3.0;
    return {shell::compute_shell_geometry(X, has_neighbour), shell::make_shell_section(thickness)};
  }

  static Internal initial_internal() { return {}; }

  /// shell::assemble_shell: residual and consistent tangent (KL15, KL16). The kernel is exactly
  /// incompressible: the model refuses 1/κ > 0 for a shell (KL12 is not implemented).
  template <class Material>
  static Status evaluate(const Geometry& g, const Vector& x, const Material& material,
                         double /*inverse_bulk_modulus*/, Internal& /*internal*/, Vector& r,
                         Matrix* K) {
    return {shell::assemble_shell(g.patch, g.section, x, material, r, K).ok, 1.0};
  }

  /// shell::compute_shell_fields: thickness averages of σ, J = 1, von Mises, -tr σ / 3 (KL21).
  template <class Material>
  static Fields fields(const Geometry& g, const Vector& x, const Material& material,
                       const Internal& /*internal*/) {
    return shell::compute_shell_fields(g.patch, g.section, x, material);
  }

  /// Π_e (KL14) [mJ].
  static double strain_energy(const Geometry& g, const Vector& x, const AnyMaterial& material,
                              double /*inverse_bulk_modulus*/, const Internal& /*internal*/) {
    return shell::compute_shell_energy(g.patch, g.section, x, material);
  }

  /// ∫ F dV over the element, V0 F with F the mid-surface's deformation gradient (KL19), constant
  /// through the thickness of a thin shell, and its reference volume V0 = A0 t.
  static Mat3d deformation_integral(const Mesh& /*mesh*/, std::span<const int, kNodes> /*nodes*/,
                                    const Geometry& g, const Vector& x, double& volume) {
    volume = g.patch.area * g.section.thickness;
    return volume * shell::mid_surface_deformation(g.patch, x);
  }

  static Fields zero_fields() { return zero_element_fields(); }
};

static_assert(ElementPolicy<ShellElement>);

}  // namespace plisse
