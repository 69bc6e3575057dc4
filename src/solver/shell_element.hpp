#pragma once
/// The rotation-free Kirchhoff-Love shell triangle (EBST, docs/theory/shell.md) as an element
/// policy of the assembly (solver/element_policy.hpp states the contract), on the mid-surface
/// of a shell mesh (mesh/shell_surface.hpp): 12 nodes, the triangle, the three nodes across its
/// sides and the six across its neighbours' other sides (KL1b), 36 unknowns [u0x, u0y, u0z, ...,
/// u11z], no pressure unknowns and no internal state.
///
/// A missing node (across an edge of the surface) repeats a node in the node list, which keeps
/// its fixed width (shell_patch_nodes). On a free or hinged side the geometry reads the
/// repetition as a missing slot (KL8), and the kernel's rows and columns of that slot are zero,
/// so its scatter onto the repeated node adds nothing. Across and beyond a clamped or symmetry
/// side (Mesh::side_mirrors) the slot is the mirror image of a slot about the side's current
/// midpoint (KL8a): its displacement a linear form in the slots that hold nodes, y = T x
/// (shell_patch_slots), so the policy evaluates the kernel at y and turns its residual and
/// tangent back, Tᵀ r and Tᵀ K T, before they are scattered; the image slot's own rows and
/// columns are then zero.
///
/// The shell has no pressure unknown: the plane-stress condition eliminates the pressure inside
/// the kernel (KL9). The state keeps four values per node (solver/dof_map.hpp); the model
/// constrains the pressure value of every node of a shell to zero (solver/mixed_model.hpp), so
/// no equation is left without stiffness.
#include <array>
#include <span>
#include <variant>
#include <vector>

#include "element/element_fields.hpp"
#include "element/shell.hpp"
#include "element/shell_output.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "solver/dof_map.hpp"
#include "solver/element_policy.hpp"
#include "solver/shell_patch.hpp"

namespace plisse {

struct ShellElement {
  static constexpr int kNodes = shell::kPatchNodes;
  static constexpr int kPressureNodes = 0;  ///< plane stress: no pressure unknowns
  static constexpr int kDof = shell::kPatchDofs;
  static constexpr int kInternalSize = 0;
  /// The points through the thickness (KL13): the section's rule has at most this many; a model
  /// with history keeps it at each (the kernel asks for the response at point q).
  static constexpr int kQuadPoints = shell::kMaxThicknessPoints;
  using Vector = shell::PatchVec;
  using Matrix = shell::PatchMat;
  using Fields = ElementFields;
  /// The patch's reference geometry and its cross-section (thickness and thickness points), and
  /// the image slots: a slot across or beyond a side of a clamped or symmetry edge is the image of
  /// a slot under the side's map about its current midpoint (shell.md, KL8a), its displacement
  /// the sum of `image_terms` (empty for an element without mirrored sides).
  struct Geometry {
    shell::ShellGeometry patch;
    shell::ShellSection section;
    std::vector<SlotTerm> image_terms;
  };
  /// ok: the element could be evaluated; min_J: the smallest det F through the thickness (1 when
  /// exactly incompressible, KL9; KL12).
  struct Status {
    bool ok = true;
    double min_J = 1.0;
  };
  /// No internal state (kInternalSize = 0).
  struct Internal {
    double* data() { return nullptr; }
    const double* data() const { return nullptr; }
  };

  /// Local node (0..11) of unknown i: the components node by node.
  static constexpr std::array<int, kDof> kLocalNode = [] {
    std::array<int, kDof> node{};
    for (int i = 0; i < kDof; ++i) node[i] = i / 3;
    return node;
  }();

  /// The triangles of the shell mesh, each with its 12-node patch (shell_patch_nodes, KL1b).
  /// Precondition: mesh.is_shell().
  static int n_elements(const Mesh& mesh) { return static_cast<int>(mesh.triangles.size()); }
  static std::array<int, kNodes> nodes(const Mesh& mesh, int e) {
    return shell_patch_nodes(mesh, e);
  }

  /// Full-state index of every element unknown: node a's (ux, uy, uz) at 3a..3a+2.
  static std::array<int, kDof> dofs(std::span<const int, kNodes> nodes) {
    std::array<int, kDof> full;
    for (int a = 0; a < kNodes; ++a)
      for (int k = 0; k < 3; ++k) full[3 * a + k] = DofMap::dof(nodes[a], k);
    return full;
  }

  /// shell::compute_shell_geometry of the patch's slots (shell_patch_slots: missing slots and
  /// mirror images, KL8, KL8a), and the section of triangle e's thickness
  /// (mesh.triangle_thickness: uniform, or its region's) with the default points (KL13). Throws
  /// plisse::Error for a degenerate patch.
  static Geometry geometry(const Mesh& mesh, int e, std::span<const int, kNodes> nodes) {
    const ShellPatchSlots slots = shell_patch_slots(mesh, nodes);
    Geometry g;
    g.image_terms = slots.image_terms;
    g.patch = shell::compute_shell_geometry(slots.X, slots.kinds);
    g.section = shell::make_shell_section(mesh.triangle_thickness[static_cast<std::size_t>(e)]);
    return g;
  }

  static Internal initial_internal() { return {}; }

  /// shell::assemble_shell: residual and consistent tangent (KL15, KL16), exactly (1/κ = 0, KL9)
  /// or nearly incompressible (KL12), with the mirrored sides' slots turned (KL8a).
  template <class Material>
  static Status evaluate(const Geometry& g, const Vector& x, const Material& material,
                         double inverse_bulk_modulus, Internal& /*internal*/, Vector& r,
                         Matrix* K) {
    const shell::ShellStatus status = shell::assemble_shell(g.patch, g.section, mirrored(g, x),
                                                            material, inverse_bulk_modulus, r, K);
    if (!g.image_terms.empty()) turn_back(g, r, K);
    return {status.ok, status.min_J};
  }

  /// shell::compute_shell_fields: thickness averages of σ and J, von Mises, -tr σ / 3 (KL21).
  template <class Material>
  static Fields fields(const Geometry& g, const Vector& x, const Material& material,
                       double inverse_bulk_modulus, const Internal& /*internal*/) {
    return shell::compute_shell_fields(g.patch, g.section, mirrored(g, x), material,
                                       inverse_bulk_modulus);
  }

  /// shell::compute_shell_outputs: the thickness, the resultants N and M, the change of
  /// curvature, and the faces' stresses and stretches (KL22-KL25). Not part of the policy
  /// contract: MixedModel::shell_outputs asks for it.
  template <class Material>
  static shell::ShellOutputs outputs(const Geometry& g, const Vector& x, const Material& material,
                                     double inverse_bulk_modulus) {
    return shell::compute_shell_outputs(g.patch, g.section, mirrored(g, x), material,
                                        inverse_bulk_modulus);
  }

  /// Π_e (KL14) [mJ].
  static double strain_energy(const Geometry& g, const Vector& x, const AnyMaterial& material,
                              double inverse_bulk_modulus, const Internal& /*internal*/) {
    return shell::compute_shell_energy(g.patch, g.section, mirrored(g, x), material,
                                       inverse_bulk_modulus);
  }

  /// ∫ F dV over the element, V0 F with F the mid-surface's deformation gradient (KL19), constant
  /// through the thickness of a thin shell, det F the mid-surface's volume ratio (1 when exactly
  /// incompressible, KL12 otherwise), and its reference volume V0 = A0 t.
  static Mat3d deformation_integral(const Mesh& /*mesh*/, std::span<const int, kNodes> /*nodes*/,
                                    const Geometry& g, const Vector& x, const AnyMaterial& material,
                                    double inverse_bulk_modulus, double& volume) {
    volume = g.patch.area * g.section.thickness;
    const Vector y = mirrored(g, x);
    double J = 1.0;
    if (inverse_bulk_modulus > 0.0) {
      const shell::ShellKinematics k = shell::compute_shell_kinematics(g.patch, g.patch.X + y);
      J = std::visit(
          [&](const auto& model) {
            return shell::evaluate_plane_stress(model, shell::nearest_section_point(g.section, 0.0),
                                                shell::in_plane_C(k.strains, 0.0), g.patch.frame,
                                                inverse_bulk_modulus)
                .J;
          },
          material);
    }
    return volume * shell::mid_surface_deformation(g.patch, y, J);
  }

  static Fields zero_fields() { return zero_element_fields(); }

  /// The patch displacements y = T x of the gathered ones x: each image slot's made the sum of
  /// its terms (KL8a), the others unchanged.
  static Vector mirrored(const Geometry& g, const Vector& x) {
    Vector y = x;
    for (const SlotTerm& t : g.image_terms) y.segment<3>(3 * t.target).setZero();
    for (const SlotTerm& t : g.image_terms)
      y.segment<3>(3 * t.target) += t.map * x.segment<3>(3 * t.source);
    return y;
  }

  /// r ← Tᵀ r and K ← Tᵀ K T for y = T x of `mirrored` (the chain rule): the image slots' rows
  /// and columns move onto their sources and are then zero.
  static void turn_back(const Geometry& g, Vector& r, Matrix* K) {
    const Vector r_patch = r;
    for (const SlotTerm& t : g.image_terms) r.segment<3>(3 * t.target).setZero();
    for (const SlotTerm& t : g.image_terms)
      r.segment<3>(3 * t.source) += t.map.transpose() * r_patch.segment<3>(3 * t.target);
    if (K == nullptr) return;
    const Matrix K_patch = *K;  // K T: columns first
    for (const SlotTerm& t : g.image_terms) K->middleCols<3>(3 * t.target).setZero();
    for (const SlotTerm& t : g.image_terms)
      K->middleCols<3>(3 * t.source) += K_patch.middleCols<3>(3 * t.target) * t.map;
    const Matrix KT = *K;  // then Tᵀ (K T)
    for (const SlotTerm& t : g.image_terms) K->middleRows<3>(3 * t.target).setZero();
    for (const SlotTerm& t : g.image_terms)
      K->middleRows<3>(3 * t.source) += t.map.transpose() * KT.middleRows<3>(3 * t.target);
  }
};

static_assert(ElementPolicy<ShellElement>);

}  // namespace plisse
