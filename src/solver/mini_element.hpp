#pragma once
/// The MINI (P1+/P1) tetrahedron as an element policy of the assembly (solver/element_policy.hpp
/// states the contract): 8 nodes in its list (the 4 corners, then the 4 nodes whose pressure
/// values the corners take: the corners themselves, or their region's pressure twins,
/// solver/pressure_twins.hpp), 16 unknowns [u0x, u0y, u0z, ..., u3z, p0, ..., p3]
/// (element/mini_layout.hpp), and the bubble (3 values) as the internal state, condensed by the
/// kernel (element/mini.hpp) and kept per element as the warm start of its next evaluation.
#include <array>
#include <span>

#include "element/mini.hpp"
#include "element/strain_energy.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "solver/dof_map.hpp"
#include "solver/element_policy.hpp"

namespace plisse {

struct MiniElement {
  static constexpr int kNodes = 2 * mini::kNodes;
  static constexpr int kPressureNodes = mini::kNodes;
  static constexpr int kDof = mini::kDof;
  static constexpr int kInternalSize = mini::kDofBubble;
  static constexpr int kQuadPoints = mini::kQuadPoints;
  using Vector = mini::ElemVec;
  using Matrix = mini::ElemMat;
  using Internal = mini::BubbleWarmStart;
  using Geometry = mini::TetGeometry;
  using Status = mini::ElementStatus;
  using Fields = ElementFields;

  /// Local node of unknown i: displacement components of corners 0..3, then the pressures from
  /// positions 4..7 of the node list.
  static constexpr std::array<int, kDof> kLocalNode = [] {
    std::array<int, kDof> node{};
    for (int i = 0; i < kDof; ++i)
      node[i] = i < mini::kDofU ? i / 3 : mini::kNodes + i - mini::kDofU;
    return node;
  }();

  /// The tetrahedra of the mesh: their corner nodes (edge nodes of a second-order mesh are
  /// unused), twice: as the carriers of their displacements and of their pressures.
  static int n_elements(const Mesh& mesh) { return mesh.n_tets(); }
  static std::array<int, kNodes> nodes(const Mesh& mesh, int e) {
    std::array<int, kNodes> n;
    for (int a = 0; a < mini::kNodes; ++a) n[a] = n[mini::kNodes + a] = mesh.tets[e][a];
    return n;
  }

  /// Full-state index of every element unknown: corner a's (ux, uy, uz) at 3a..3a+2, its
  /// pressure (the value of node list position 4 + a) at kDofU + a.
  static std::array<int, kDof> dofs(std::span<const int, kNodes> nodes) {
    std::array<int, kDof> full;
    for (int a = 0; a < mini::kNodes; ++a) {
      for (int k = 0; k < 3; ++k) full[3 * a + k] = DofMap::dof(nodes[a], k);
      full[mini::kDofU + a] = DofMap::dof(nodes[mini::kNodes + a], 3);
    }
    return full;
  }

  /// mini::compute_tet_geometry of the corners (throws plisse::Error for a degenerate one).
  static Geometry geometry(const Mesh& mesh, int /*e*/, std::span<const int, kNodes> nodes) {
    return mini::compute_tet_geometry(
        {mesh.nodes[nodes[0]], mesh.nodes[nodes[1]], mesh.nodes[nodes[2]], mesh.nodes[nodes[3]]});
  }

  /// No bubble displacement, no prediction.
  static Internal initial_internal() { return {}; }

  /// mini::assemble_mini: the condensed residual and tangent, warm-started from the bubble's
  /// first-order prediction at x; `warm` receives the converged bubble and its sensitivity.
  template <class Material>
  static Status evaluate(const Geometry& g, const Vector& x, const Material& material,
                         double inverse_bulk_modulus, Internal& warm, Vector& r, Matrix* K) {
    return mini::assemble_mini(g, x, material, inverse_bulk_modulus, warm, r, K);
  }

  /// mini::compute_element_fields: volume averages of σ, J, von Mises and p.
  template <class Material>
  static Fields fields(const Geometry& g, const Vector& x, const Material& material,
                       double /*inverse_bulk_modulus*/, const Internal& bubble) {
    return mini::compute_element_fields(g, x, material, bubble.b);
  }

  /// mini::compute_strain_energy, isochoric plus volumetric part [mJ].
  static double strain_energy(const Geometry& g, const Vector& x, const AnyMaterial& material,
                              double inverse_bulk_modulus, const Internal& bubble) {
    return mini::compute_strain_energy(g, x, material, inverse_bulk_modulus, bubble.b).total();
  }

  /// ∫ F dV over the element and its reference volume V0. The bubble vanishes on the element's
  /// boundary, so the mean of F is that of its linear part: ∫ F dV = V0 dx dX⁻¹ (divergence
  /// theorem), with dX, dx the edge vectors X_a - X_0 and x_a - x_0 (a = 1..3).
  static Mat3d deformation_integral(const Mesh& mesh, std::span<const int, kNodes> nodes,
                                    const Geometry& /*g*/, const Vector& x,
                                    const AnyMaterial& /*material*/,
                                    double /*inverse_bulk_modulus*/, double& volume) {
    const Vec3d X0 = mesh.nodes[nodes[0]];
    Mat3d dX, dx;
    for (int a = 1; a < 4; ++a) {
      dX.col(a - 1) = mesh.nodes[nodes[a]] - X0;
      dx.col(a - 1) = dX.col(a - 1);
      for (int k = 0; k < 3; ++k) dx(k, a - 1) += x[mini::dof_u(a, k)] - x[mini::dof_u(0, k)];
    }
    volume = dX.determinant() / 6.0;
    return volume * dx * dX.inverse();
  }

  /// All fields zero (the entries of elements another rank owns, before the sum over ranks).
  static Fields zero_fields() { return zero_element_fields(); }
};

static_assert(ElementPolicy<MiniElement>);

}  // namespace plisse
