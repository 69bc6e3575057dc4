#pragma once
/// What an element type provides to the assembly (solver/element_assembly.hpp): a compile-time
/// policy type, all static, that the one element loop, the scatter into the residual and the
/// tangent, the output fields and the checkpoints are written against. A new element family is a
/// new policy; the loop is not copied. solver/mini_element.hpp is the MINI tetrahedron's,
/// solver/taylor_hood_element.hpp the Taylor-Hood tetrahedron's, solver/shell_element.hpp the
/// shell triangle's.
///
/// Sizes
///   kNodes         nodes in the element's node list (the width of its ElementNodes; the tangent
///                  layout stores one position per pair of them; a node may appear twice).
///                  MINI: 8, Taylor-Hood: 14, shell: 12.
///   kPressureNodes the last kPressureNodes positions of the node list carry the element's
///                  pressure unknowns, one per corner: nodes(mesh, e) lists there the corners,
///                  which are its first kPressureNodes positions, and the assembly puts a
///                  region's pressure twin in a corner's place where the model gives the regions
///                  their own pressures (solver/pressure_twins.hpp); without twins it keeps
///                  the other positions only. MINI and Taylor-Hood: 4, shell: 0.
///   kDof           element unknowns seen by the global solver, all nodal values. MINI: 16,
///                  Taylor-Hood: 34, shell: 36.
///   kInternalSize  doubles of internal state per element, condensed out of the global system
///                  and carried from one evaluation to the next (a warm start). MINI: 3 (bubble).
///                  May be 0.
///   kQuadPoints    quadrature points per element: where a model with history keeps it (the
///                  kernels ask for the response at point q, evaluate_at_point).
/// Types
///   Vector, Matrix  fixed-size Eigen types of kDof and kDof x kDof doubles (element unknowns,
///                   residual, tangent). No heap.
///   Internal        the internal state: kInternalSize contiguous doubles at data().
///   Geometry        the reference data of one element, computed once.
///   Status          the outcome of one evaluation, with `bool ok` (false: the element could not
///                   be evaluated; r and K are then zero) and `double min_J` (smallest det F).
///   Fields          output averages of one element: doubles only (summed over the ranks as an
///                   array of doubles).
/// Dof layout
///   kLocalNode[i]   the position in the node list of the node that carries unknown i.
///   nodes(mesh, e)  the node list of element e; n_elements(mesh) the number of elements.
///   dofs(nodes)     the full-state index of every unknown (solver/dof_map.hpp: DofMap::dof).
/// Kernels (templates on the material, any model of material/registry.hpp; thread-safe, no heap
/// allocation: they run concurrently on different elements)
///   geometry(mesh, e, nodes)                 Geometry of element e, whose nodes these are.
///   initial_internal()                       Internal state of the undeformed body.
///   evaluate(g, x, material, 1/κ, internal, r, K)
///       residual r (and the tangent K = dr/dx when K is not null; both overwritten) at element
///       unknowns x; updates `internal` (left unchanged when the status is not ok).
///   fields(g, x, material, 1/κ, internal)    output averages at (x, internal).
///   strain_energy(g, x, material, 1/κ, internal)  stored energy [mJ] at (x, internal).
///   deformation_integral(mesh, nodes, g, x, material, 1/κ, V0)  ∫ F dV over the element at x
///                                            (the material and 1/κ matter to a shell, whose
///                                            thickness stretch they decide); V0 receives its
///                                            reference volume.
///   zero_fields()                            Fields of zeros.
#include <array>
#include <concepts>
#include <span>
#include <variant>

#include "material/registry.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// The contract above, checked at compile time (the material kernels with the registry's first
/// model).
template <class E>
concept ElementPolicy = requires(const Mesh& mesh, std::span<const int, E::kNodes> nodes,
                                 const typename E::Geometry& g, const typename E::Vector& x,
                                 const std::variant_alternative_t<0, AnyMaterial>& material,
                                 const AnyMaterial& any_material, typename E::Internal& internal,
                                 typename E::Vector& r, typename E::Matrix* K, double& volume) {
  { E::kNodes } -> std::convertible_to<int>;
  { E::kPressureNodes } -> std::convertible_to<int>;
  { E::kDof } -> std::convertible_to<int>;
  { E::kInternalSize } -> std::convertible_to<int>;
  { E::kQuadPoints } -> std::convertible_to<int>;
  { E::kLocalNode } -> std::convertible_to<std::array<int, E::kDof>>;
  { E::n_elements(mesh) } -> std::same_as<int>;
  { E::nodes(mesh, 0) } -> std::same_as<std::array<int, E::kNodes>>;
  { E::dofs(nodes) } -> std::same_as<std::array<int, E::kDof>>;
  { E::geometry(mesh, 0, nodes) } -> std::same_as<typename E::Geometry>;
  { E::initial_internal() } -> std::same_as<typename E::Internal>;
  { internal.data() } -> std::same_as<double*>;
  { E::evaluate(g, x, material, 0.0, internal, r, K) } -> std::same_as<typename E::Status>;
  { E::fields(g, x, material, 0.0, internal) } -> std::same_as<typename E::Fields>;
  { E::strain_energy(g, x, any_material, 0.0, internal) } -> std::same_as<double>;
  { E::zero_fields() } -> std::same_as<typename E::Fields>;
  { E::deformation_integral(mesh, nodes, g, x, any_material, 0.0, volume) } -> std::same_as<Mat3d>;
}
&&sizeof(typename E::Fields) % sizeof(double) == 0;

}  // namespace plisse
