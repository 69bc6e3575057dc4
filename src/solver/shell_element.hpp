#pragma once
/// The rotation-free Kirchhoff-Love shell triangle (EBST, docs/theory/shell.md) as an element
/// policy of the assembly (solver/element_policy.hpp states the contract), on the mid-surface
/// of a shell mesh (mesh/shell_surface.hpp): 6 nodes, the triangle and the three nodes across
/// its sides (KL1), 18 unknowns [u0x, u0y, u0z, ..., u5z], no pressure unknowns and no internal
/// state.
///
/// A side without a neighbour (an edge of the surface) repeats the triangle's corner opposite
/// it in the node list (node 3 + i = node i): the node list keeps its fixed width. On a free or
/// hinged side the geometry reads the repetition as the missing neighbour (KL8), and the kernel's
/// rows and columns of that slot are zero, so its scatter onto the corner adds nothing. On a
/// clamped or symmetry side (Mesh::side_mirrors) the slot is the mirror image of node i (KL8a):
/// its displacement R u_i, R the mirror's linear part, so the policy evaluates the kernel at that
/// displacement and turns the slot's rows and columns back by R (R = Rᵀ = R⁻¹) before they are
/// scattered onto node i.
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
  /// The patch's reference geometry and its cross-section (thickness and thickness points), and
  /// the mirrored sides: side i of a clamped or symmetry edge reads its missing node as the image
  /// of node i under the map of Mesh::side_mirrors (shell.md, KL8a), whose linear part is
  /// `mirror[i]` (the identity for every other side).
  struct Geometry {
    shell::ShellGeometry patch;
    shell::ShellSection section;
    std::array<bool, 3> mirrored{};
    std::array<Mat3d, 3> mirror{Mat3d::Identity(), Mat3d::Identity(), Mat3d::Identity()};
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

  /// shell::compute_shell_geometry of the patch, a repeated corner read as a missing neighbour or,
  /// on a side of Mesh::side_mirrors, replaced by its mirror image, and the section of the
  /// element's thickness (the mean of its corners', mesh.shell_thickness) with the default points
  /// (KL13). Throws plisse::Error for a degenerate patch.
  static Geometry geometry(const Mesh& mesh, std::span<const int, kNodes> nodes) {
    Geometry g;
    shell::PatchPositions X;
    shell::NeighbourFlags has_neighbour;
    for (int a = 0; a < kNodes; ++a) X[a] = mesh.nodes[nodes[a]];
    for (int i = 0; i < 3; ++i) {
      has_neighbour[i] = nodes[3 + i] != nodes[i];
      if (has_neighbour[i] || mesh.side_mirrors.empty()) continue;
      const auto m = mesh.side_mirrors.find({nodes[(i + 1) % 3], nodes[(i + 2) % 3]});
      if (m == mesh.side_mirrors.end()) continue;
      g.mirrored[i] = has_neighbour[i] = true;
      g.mirror[i] = m->second.map;
      X[3 + i] = m->second.point + m->second.map * (X[i] - m->second.point);
    }
    double thickness = 0.0;
    for (int i = 0; i < 3; ++i) thickness += mesh.shell_thickness[nodes[i]] / 3.0;
    g.patch = shell::compute_shell_geometry(X, has_neighbour);
    g.section = shell::make_shell_section(thickness);
    return g;
  }

  static Internal initial_internal() { return {}; }

  /// shell::assemble_shell: residual and consistent tangent (KL15, KL16), with the mirrored
  /// sides' slots turned (KL8a). The kernel is exactly incompressible: the model refuses
  /// 1/κ > 0 for a shell (KL12 is not implemented).
  template <class Material>
  static Status evaluate(const Geometry& g, const Vector& x, const Material& material,
                         double /*inverse_bulk_modulus*/, Internal& /*internal*/, Vector& r,
                         Matrix* K) {
    const bool ok = shell::assemble_shell(g.patch, g.section, mirrored(g, x), material, r, K).ok;
    for (int i = 0; i < 3; ++i) {
      if (!g.mirrored[i]) continue;
      const int s = 3 * (3 + i);
      r.segment<3>(s) = g.mirror[i] * r.segment<3>(s);
      if (K == nullptr) continue;
      K->middleRows<3>(s) = g.mirror[i] * K->middleRows<3>(s);
      K->middleCols<3>(s) = K->middleCols<3>(s) * g.mirror[i];
    }
    return {ok, 1.0};
  }

  /// shell::compute_shell_fields: thickness averages of σ, J = 1, von Mises, -tr σ / 3 (KL21).
  template <class Material>
  static Fields fields(const Geometry& g, const Vector& x, const Material& material,
                       const Internal& /*internal*/) {
    return shell::compute_shell_fields(g.patch, g.section, mirrored(g, x), material);
  }

  /// shell::compute_shell_outputs: the thickness, the resultants N and M, the change of
  /// curvature, and the faces' stresses and stretches (KL22-KL25). Not part of the policy
  /// contract: MixedModel::shell_outputs asks for it.
  template <class Material>
  static shell::ShellOutputs outputs(const Geometry& g, const Vector& x, const Material& material) {
    return shell::compute_shell_outputs(g.patch, g.section, mirrored(g, x), material);
  }

  /// Π_e (KL14) [mJ].
  static double strain_energy(const Geometry& g, const Vector& x, const AnyMaterial& material,
                              double /*inverse_bulk_modulus*/, const Internal& /*internal*/) {
    return shell::compute_shell_energy(g.patch, g.section, mirrored(g, x), material);
  }

  /// ∫ F dV over the element, V0 F with F the mid-surface's deformation gradient (KL19), constant
  /// through the thickness of a thin shell, and its reference volume V0 = A0 t.
  static Mat3d deformation_integral(const Mesh& /*mesh*/, std::span<const int, kNodes> /*nodes*/,
                                    const Geometry& g, const Vector& x, double& volume) {
    volume = g.patch.area * g.section.thickness;
    return volume * shell::mid_surface_deformation(g.patch, mirrored(g, x));
  }

  static Fields zero_fields() { return zero_element_fields(); }

  /// The element's displacements with each mirrored side's slot, gathered as node i's u_i, made
  /// the mirror image's R u_i (KL8a).
  static Vector mirrored(const Geometry& g, const Vector& x) {
    Vector y = x;
    for (int i = 0; i < 3; ++i)
      if (g.mirrored[i]) y.segment<3>(3 * (3 + i)) = g.mirror[i] * x.segment<3>(3 * i);
    return y;
  }
};

static_assert(ElementPolicy<ShellElement>);

}  // namespace plisse
