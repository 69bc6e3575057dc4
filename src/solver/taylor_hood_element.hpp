#pragma once
/// The Taylor-Hood (P2/P1) tetrahedron as an element policy of the assembly
/// (solver/element_policy.hpp states the contract): 14 nodes in its list (corners, then the edge
/// nodes of a second-order mesh, then the 4 nodes whose pressure values the corners take: the
/// corners themselves, or their region's pressure twins, solver/pressure_twins.hpp), 34 unknowns
/// [u0x, ..., u9z, p0, ..., p3] (element/taylor_hood_geometry.hpp) and no internal state. The
/// pressure unknowns of the edge nodes are not used by the element; the model constrains them
/// (solver/mixed_model.hpp).
#include <array>
#include <span>

#include "element/taylor_hood.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "solver/dof_map.hpp"
#include "solver/element_policy.hpp"

namespace plisse {

struct TaylorHoodElement {
  static constexpr int kNodes = taylor_hood::kNodes + taylor_hood::kCorners;
  static constexpr int kPressureNodes = taylor_hood::kCorners;
  static constexpr int kDof = taylor_hood::kDof;
  static constexpr int kInternalSize = 0;
  static constexpr int kQuadPoints = taylor_hood::kQuadPoints;
  using Vector = taylor_hood::ElemVec;
  using Matrix = taylor_hood::ElemMat;
  using Geometry = taylor_hood::Geometry;
  using Status = taylor_hood::ElementStatus;
  using Fields = ElementFields;
  /// No internal state (kInternalSize = 0).
  struct Internal {
    double* data() { return nullptr; }
    const double* data() const { return nullptr; }
  };

  /// Local node of unknown i: displacement components of nodes 0..9, then the corners' pressures
  /// from positions 10..13 of the node list.
  static constexpr std::array<int, kDof> kLocalNode = [] {
    std::array<int, kDof> node{};
    for (int i = 0; i < kDof; ++i)
      node[i] = i < taylor_hood::kDofU ? i / 3 : taylor_hood::kNodes + i - taylor_hood::kDofU;
    return node;
  }();

  /// The tetrahedra of a second-order mesh: corners, then edge nodes (Gmsh's edge order), then
  /// the corners again as the carriers of the pressures. Precondition: mesh.order() == 2.
  static int n_elements(const Mesh& mesh) { return mesh.n_tets(); }
  static std::array<int, kNodes> nodes(const Mesh& mesh, int e) {
    std::array<int, kNodes> n;
    for (int a = 0; a < 4; ++a) n[a] = n[taylor_hood::kNodes + a] = mesh.tets[e][a];
    for (int k = 0; k < 6; ++k) n[4 + k] = mesh.tet_edge_nodes[e][k];
    return n;
  }

  /// Full-state index of every element unknown: node a's (ux, uy, uz) at 3a..3a+2, corner a's
  /// pressure (the value of node list position 10 + a) at kDofU + a.
  static std::array<int, kDof> dofs(std::span<const int, kNodes> nodes) {
    std::array<int, kDof> full;
    for (int a = 0; a < taylor_hood::kNodes; ++a)
      for (int k = 0; k < 3; ++k) full[3 * a + k] = DofMap::dof(nodes[a], k);
    for (int a = 0; a < taylor_hood::kCorners; ++a)
      full[taylor_hood::kDofU + a] = DofMap::dof(nodes[taylor_hood::kNodes + a], 3);
    return full;
  }

  /// taylor_hood::compute_geometry of the 10 nodes (throws plisse::Error for an inverted one).
  static Geometry geometry(const Mesh& mesh, int /*e*/, std::span<const int, kNodes> nodes) {
    std::array<Vec3d, taylor_hood::kNodes> X;
    for (int a = 0; a < taylor_hood::kNodes; ++a) X[a] = mesh.nodes[nodes[a]];
    return taylor_hood::compute_geometry(X);
  }

  static Internal initial_internal() { return {}; }

  /// taylor_hood::assemble: residual and consistent tangent.
  template <class Material>
  static Status evaluate(const Geometry& g, const Vector& x, const Material& material,
                         double inverse_bulk_modulus, Internal& /*internal*/, Vector& r,
                         Matrix* K) {
    return taylor_hood::assemble(g, x, material, inverse_bulk_modulus, r, K);
  }

  /// taylor_hood::compute_element_fields: volume averages of σ, J, von Mises and p.
  template <class Material>
  static Fields fields(const Geometry& g, const Vector& x, const Material& material,
                       double /*inverse_bulk_modulus*/, const Internal& /*internal*/) {
    return taylor_hood::compute_element_fields(g, x, material);
  }

  /// taylor_hood::compute_strain_energy [mJ].
  static double strain_energy(const Geometry& g, const Vector& x, const AnyMaterial& material,
                              double inverse_bulk_modulus, const Internal& /*internal*/) {
    return std::visit(
        [&](const auto& m) {
          return taylor_hood::compute_strain_energy(g, x, m, inverse_bulk_modulus);
        },
        material);
  }

  /// ∫ F dV over the element (by its quadrature) and its reference volume.
  static Mat3d deformation_integral(const Mesh& /*mesh*/, std::span<const int, kNodes> /*nodes*/,
                                    const Geometry& g, const Vector& x,
                                    const AnyMaterial& /*material*/,
                                    double /*inverse_bulk_modulus*/, double& volume) {
    volume = g.volume;
    return taylor_hood::deformation_integral(g, x);
  }

  static Fields zero_fields() { return zero_element_fields(); }
};

static_assert(ElementPolicy<TaylorHoodElement>);

}  // namespace plisse
