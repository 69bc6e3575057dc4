#pragma once
/// The element part of the assembly, written once for any element policy
/// (solver/element_policy.hpp): the element data (geometry, internal state) and the threaded,
/// chunked element loop with its scatter into the residual and the tangent.
///
/// Threads, same bits: the local elements are evaluated in parallel a chunk at a time (each
/// writes only its own result buffer and its own internal state), then each chunk is added on
/// the calling thread in element order. Every entry therefore receives the same floating-point
/// additions in the same order as a serial loop: the results do not depend on the thread count.
/// No heap allocation in the loops: the chunk buffer is kept between assemblies.
///
/// Uses OpenMP: include it only in code compiled with OpenMP (solver/CMakeLists.txt).
#include <omp.h>
#include <petscmat.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cstddef>
#include <exception>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "core/error.hpp"
#include "material/inelastic_points.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "solver/assembly_status.hpp"
#include "solver/distribution.hpp"
#include "solver/dof_map.hpp"
#include "solver/element_materials.hpp"
#include "solver/element_nodes.hpp"
#include "solver/element_policy.hpp"
#include "solver/petsc_call.hpp"
#include "solver/pressure_twins.hpp"
#include "solver/tangent_layout.hpp"

namespace plisse {

/// Elements evaluated per chunk of the element loop (MINI results 2.2 kB each: 9 MB of buffer).
/// Each chunk ends in a barrier, which waits for the slowest thread: on a machine with more
/// runnable processes than cores a descheduled thread holds it for a whole time slice, so chunks
/// are large (with 512 a 2-thread residual was 8 times slower than a serial one under such load).
inline constexpr int kChunkElements = 4096;

template <ElementPolicy Element>
class ElementAssembly {
 public:
  using Fields = typename Element::Fields;

  /// The elements of `mesh` (borrowed only here), their geometry and initial internal state, and
  /// the material of each (`materials`: at least one model, an index per element or none; rigid
  /// elements are skipped by the assembly and the stored energy, and report the fields of an
  /// unstressed element). `twins`, when it has any, gives each element the nodes of its
  /// corners' pressure values (PressureTwins::carrier; a family with pressure unknowns only).
  ElementAssembly(const Mesh& mesh, ElementMaterials materials, const PressureTwins& twins = {})
      : materials_(std::move(materials)) {
    const int n = Element::n_elements(mesh);
    PLISSE_CHECK(!materials_.materials.empty() &&
                     materials_.inverse_bulk_moduli.size() == materials_.materials.size() &&
                     (materials_.of_element.empty() ||
                      materials_.of_element.size() == static_cast<std::size_t>(n)),
                 "element materials: " << materials_.materials.size() << " models, "
                                       << materials_.of_element.size() << " indices for " << n
                                       << " elements");
    for (int m : materials_.of_element)
      PLISSE_CHECK(m == ElementMaterials::kRigid ||
                       (m >= 0 && m < static_cast<int>(materials_.materials.size())),
                   "element material index " << m << " out of range");
    // Without twins the carriers are the corners: the lists keep the other positions only, and
    // the layout reads the corners for the pressures (kCompactLocalNode), so a model without
    // regions stores and scatters what it did before twins existed.
    width_ = twins.carrier.empty() ? kCompactWidth : Element::kNodes;
    nodes_.reserve(static_cast<std::size_t>(n) * width_);
    geometry_.reserve(n);
    PLISSE_CHECK(twins.carrier.empty() || (Element::kPressureNodes == 4 &&
                                           twins.carrier.size() == 4 * static_cast<std::size_t>(n)),
                 "pressure twins: " << twins.carrier.size() << " corners for " << n
                                    << " elements of " << Element::kPressureNodes
                                    << " pressure nodes");
    for (int e = 0; e < n; ++e) {
      std::array<int, Element::kNodes> nodes = Element::nodes(mesh, e);
      // The corners' pressure carriers: the corners themselves, or their region's twins.
      constexpr int first = Element::kNodes - Element::kPressureNodes;
      for (int a = 0; a < Element::kPressureNodes; ++a)
        nodes[first + a] = twins.carrier_of(e, a, nodes[first + a]);
      nodes_.insert(nodes_.end(), nodes.begin(), nodes.begin() + width_);
      geometry_.push_back(Element::geometry(mesh, e, nodes));
    }
    internal_.assign(n, Element::initial_internal());
    converged_internal_ = internal_;
    // The history of the points of models with viscoelasticity or Mullins softening, element
    // after element (none for elastic and rigid elements); all zero is the undeformed body.
    history_offset_.assign(static_cast<std::size_t>(n) + 1, 0);
    for (int e = 0; e < n; ++e)
      history_offset_[e + 1] = history_offset_[e] + static_cast<std::size_t>(Element::kQuadPoints) *
                                                        materials_.history_size(materials_.of(e));
    history_.assign(history_offset_.back(), 0.0);
    converged_history_ = history_;
  }

  /// The element node lists (a view of this object's storage): Element::kNodes per element, or
  /// without pressure twins all but the last Element::kPressureNodes (the carriers, which are
  /// then the corners, the first Element::kPressureNodes).
  ElementNodes nodes() const { return {nodes_, width_}; }
  /// The material of every element.
  const ElementMaterials& materials() const { return materials_; }
  /// Number of elements (all ranks hold all of them).
  int n_elements() const { return static_cast<int>(geometry_.size()); }
  /// True when some element's points carry history (viscoelasticity, Mullins softening).
  bool has_history() const { return !history_.empty(); }
  /// The time [s] from the last converged state to the state the next assemblies evaluate: the
  /// step of the history update (material/inelastic.hpp). 0 evaluates the converged response.
  void set_time_step(double dt) { dt_ = dt; }

  /// Adds the residual of the local elements of `distribution` at the full state `state` to
  /// `residual` (full-state layout) and updates their internal state. Collective (the status is
  /// reduced over the ranks).
  AssemblyStatus add_residual(const Distribution& distribution, std::span<const double> state,
                              std::span<double> residual, int threads) {
    return evaluate(distribution, state, false, threads, [&](int e, const Result& out) {
      const std::array<int, Element::kDof> full = dofs(e);
      for (int i = 0; i < Element::kDof; ++i) residual[full[i]] += out.r[i];
    });
  }

  /// Adds the tangent of the local elements into the owned rows `values` of a matrix with
  /// `layout` (TangentLayout::open_values) and updates their internal state. Collective.
  AssemblyStatus add_tangent(const Distribution& distribution, std::span<const double> state,
                             const TangentLayout& layout, PetscScalar* values, int threads) {
    const DofMap& dof_map = distribution.dofs();
    return evaluate(distribution, state, true, threads, [&](int e, const Result& out) {
      const std::array<int, Element::kDof> full = dofs(e);
      std::array<int, Element::kDof> equations;
      for (int i = 0; i < Element::kDof; ++i) equations[i] = dof_map.equation(full[i]);
      layout.add_element(e, equations,
                         width_ == Element::kNodes ? Element::kLocalNode : kCompactLocalNode, out.K,
                         values);
    });
  }

  /// The same into the owned rows of any matrix K through MatSetValues (same values, slower).
  /// Collective.
  AssemblyStatus add_tangent(const Distribution& distribution, std::span<const double> state, Mat K,
                             int threads) {
    const DofMap& dof_map = distribution.dofs();
    return evaluate(distribution, state, true, threads, [&](int e, const Result& out) {
      const std::array<int, Element::kDof> full = dofs(e);
      std::array<PetscInt, Element::kDof> rows, columns;
      for (int i = 0; i < Element::kDof; ++i) {
        columns[i] = dof_map.equation(full[i]);
        rows[i] = distribution.owns_equation(columns[i]) ? columns[i] : -1;  // owned rows only
      }
      // PETSc takes row-major blocks; negative indices (constrained) are skipped.
      const Eigen::Matrix<double, Element::kDof, Element::kDof, Eigen::RowMajor> k_row = out.K;
      PLISSE_PETSC(MatSetValues(K, Element::kDof, rows.data(), Element::kDof, columns.data(),
                                k_row.data(), ADD_VALUES));
    });
  }

  /// Output fields of every element at `state` (Element::fields): per_element. Collective.
  std::vector<Fields> fields(const Distribution& distribution, std::span<const double> state,
                             int threads) const {
    return per_element(distribution, state, threads, Element::zero_fields(),
                       [](const auto& geometry, const auto& x, const auto& material,
                          double inverse_bulk_modulus, const auto& internal) {
                         return Element::fields(geometry, x, material, inverse_bulk_modulus,
                                                internal);
                       });
  }

  /// evaluate(geometry, x, material, 1/κ, internal) of every element at `state`, for output: each
  /// rank evaluates its owned elements, in parallel, and the ranks' arrays (`zero` on the elements
  /// of other ranks) are summed, so every rank gets every element's value. R holds doubles only
  /// (it is summed as a flat array). A rigid element is evaluated undeformed (it only
  /// translates), with model 0, exactly incompressible, at zero pressure: F = I and no stress,
  /// also for a shell triangle whose patch reaches across into the deformable body; a model with
  /// history gives the response of its last converged history. Collective.
  template <class R, class Evaluate>
  std::vector<R> per_element(const Distribution& distribution, std::span<const double> state,
                             int threads, const R& zero, Evaluate&& evaluate) const {
    static_assert(sizeof(R) % sizeof(double) == 0 && alignof(R) == alignof(double),
                  "per_element sums R over the ranks as an array of doubles");
    std::vector<R> out(n_elements(), zero);
    const std::vector<int>& owned = distribution.owned_elements();
    const int n = static_cast<int>(owned.size());
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
    for (int k = 0; k < n; ++k) {
      const int e = owned[k];
      try {
        const std::array<int, Element::kDof> full = dofs(e);
        typename Element::Vector x = gather(full, state);
        int m = materials_.of(e);
        double inverse_bulk_modulus = 0.0;
        if (m == ElementMaterials::kRigid) {
          // Any model, undeformed and at zero pressure, gives F, J = 1 and zero stresses.
          x.setZero();
          m = 0;
        } else {
          inverse_bulk_modulus = materials_.inverse_bulk_moduli[m];
        }
        // With history: the response of the last converged history (dt = 0, nothing written).
        out[e] = with_material(e, m, {}, 0.0, [&](const auto& material) -> R {
          return evaluate(geometry_[e], x, material, inverse_bulk_modulus, internal_[e]);
        });
      } catch (...) {
#pragma omp critical(plisse_element_output_error)
        if (!error) error = std::current_exception();
      }
    }
    if (error) std::rethrow_exception(error);
    // Every element is owned by one rank: the sum of the ranks' arrays is every element's value.
    distribution.sum_over_ranks(reinterpret_cast<double*>(out.data()),
                                out.size() * (sizeof(R) / sizeof(double)));
    return out;
  }

  /// Stored energy of the body at `state` [mJ]: the sum over the elements in element order of
  /// each owner's, summed over the ranks. Collective.
  double strain_energy(const Distribution& distribution, std::span<const double> state) const {
    double energy = 0.0;
    for (int e : distribution.owned_elements()) {
      const int m = materials_.of(e);
      if (m == ElementMaterials::kRigid) continue;
      energy +=
          Element::strain_energy(geometry_[e], gather(dofs(e), state), materials_.materials[m],
                                 materials_.inverse_bulk_moduli[m], internal_[e]);
    }
    distribution.sum_over_ranks(&energy, 1);
    return energy;
  }

  /// Calls visit(e, V0, ∫ F dV) for every element e in element order at `state`: its reference
  /// volume [mm^3] and the integral of the deformation gradient over it (Element::
  /// deformation_integral). `mesh` is the mesh the assembly was built from. Every rank, all
  /// elements (the state is whole on every rank).
  template <class Visit>
  void for_each_deformation(const Mesh& mesh, std::span<const double> state, Visit&& visit) const {
    for (int e = 0; e < n_elements(); ++e) {
      double volume = 0.0;
      const int m = materials_.of(e);
      const bool rigid = m == ElementMaterials::kRigid;  // moves rigidly: model 0, J = 1
      const std::array<int, Element::kNodes> nodes = node_list(e);
      const Mat3d integral = Element::deformation_integral(
          mesh, std::span<const int, Element::kNodes>(nodes), geometry_[e], gather(dofs(e), state),
          materials_.materials[rigid ? 0 : m], rigid ? 0.0 : materials_.inverse_bulk_moduli[m],
          volume);
      visit(e, volume, integral);
    }
  }

  /// Remember / return to the internal state and the points' history of the last converged
  /// state. The history must have been evaluated at the state being saved (MixedModel evaluates
  /// the residual there first).
  void save_converged() {
    converged_internal_ = internal_;
    converged_history_ = history_;
  }
  void restore_converged() {
    internal_ = converged_internal_;
    history_ = converged_history_;
  }

  /// Doubles of internal state of all elements: kInternalSize per element, then the history of
  /// their points.
  std::size_t n_internal_values() const {
    return internal_.size() * static_cast<std::size_t>(Element::kInternalSize) + history_.size();
  }
  /// The converged internal state of every element, element after element, then the converged
  /// history of their points, element after element, as each element's owner holds them.
  /// Collective.
  std::vector<double> converged_values(const Distribution& distribution) const {
    constexpr int kSize = Element::kInternalSize;
    std::vector<double> values;
    values.reserve(n_internal_values());
    for (const auto& s : converged_internal_)
      values.insert(values.end(), s.data(), s.data() + kSize);
    values.insert(values.end(), converged_history_.begin(), converged_history_.end());
    if (distribution.n_ranks() > 1) {
      // Each rank's internal state is current only on its own elements: the owners' values,
      // summed with zeros from everyone else.
      std::vector<char> mine(converged_internal_.size(), 0);
      for (int e : distribution.owned_elements()) mine[e] = 1;
      const std::size_t bubbles = converged_internal_.size() * kSize;
      for (std::size_t e = 0; e < mine.size(); ++e) {
        if (mine[e]) continue;
        std::fill_n(values.begin() + e * kSize, kSize, 0.0);
        std::fill(values.begin() + bubbles + history_offset_[e],
                  values.begin() + bubbles + history_offset_[e + 1], 0.0);
      }
      distribution.sum_over_ranks(values.data(), values.size());
    }
    return values;
  }
  /// Makes `values` (n_internal_values(), as from converged_values) the current and the
  /// converged internal state.
  void restore(std::span<const double> values) {
    for (std::size_t e = 0; e < internal_.size(); ++e) {
      internal_[e] = Element::initial_internal();  // beyond kInternalSize: a cache, now stale
      std::copy_n(values.data() + e * Element::kInternalSize, Element::kInternalSize,
                  internal_[e].data());
    }
    std::copy(values.end() - static_cast<std::ptrdiff_t>(history_.size()), values.end(),
              history_.begin());
    converged_internal_ = internal_;
    converged_history_ = history_;
  }

 private:
  /// Element results of one chunk of the element loop.
  struct Result {
    typename Element::Vector r;
    typename Element::Matrix K;
    typename Element::Status status;
    bool rigid;  ///< a rigid element: nothing evaluated, nothing to add
  };

  /// Positions of a node list without its pressure carriers.
  static constexpr int kCompactWidth = Element::kNodes - Element::kPressureNodes;
  /// Element::kLocalNode for the compact lists: a pressure's carrier is its corner, position a.
  static constexpr std::array<int, Element::kDof> kCompactLocalNode = [] {
    std::array<int, Element::kDof> node = Element::kLocalNode;
    for (int& a : node)
      if (a >= kCompactWidth) a -= kCompactWidth;
    return node;
  }();
  /// Element e's whole node list (Element::nodes with its carriers).
  std::array<int, Element::kNodes> node_list(int e) const {
    std::array<int, Element::kNodes> nodes;
    const int* stored = nodes_.data() + static_cast<std::size_t>(e) * width_;
    for (int a = 0; a < width_; ++a) nodes[a] = stored[a];
    for (int a = width_; a < Element::kNodes; ++a) nodes[a] = stored[a - kCompactWidth];
    return nodes;
  }
  std::array<int, Element::kDof> dofs(int e) const {
    const std::array<int, Element::kNodes> nodes = node_list(e);
    return Element::dofs(std::span<const int, Element::kNodes>(nodes));
  }
  /// Element e's point history: the current (written by evaluations) and the converged one.
  std::span<double> history(int e) {
    return std::span<double>(history_).subspan(history_offset_[e],
                                               history_offset_[e + 1] - history_offset_[e]);
  }
  std::span<const double> converged_history(int e) const {
    return std::span<const double>(converged_history_)
        .subspan(history_offset_[e], history_offset_[e + 1] - history_offset_[e]);
  }
  /// f(material) with model m for element e: the elastic model itself or, when e's own model
  /// carries history, that model bound to e's converged history, writing the new one to `now`
  /// (may be empty) for a time step dt. (A rigid element has no history: its fields evaluate
  /// model 0 alone.)
  template <class F>
  decltype(auto) with_material(int e, int m, std::span<double> now, double dt, F&& f) const {
    if (const InelasticLaw* law = materials_.law(materials_.of(e)))
      return f(InelasticPoints{&materials_.materials[m], law, converged_history(e), now, dt});
    return std::visit(f, materials_.materials[m]);
  }
  static typename Element::Vector gather(const std::array<int, Element::kDof>& full,
                                         std::span<const double> state) {
    typename Element::Vector x;
    for (int i = 0; i < Element::kDof; ++i) x[i] = state[full[i]];
    return x;
  }

  /// Evaluates every local element (residual, and tangent when `with_tangent`) in parallel, a
  /// chunk at a time, and calls scatter(e, result) in element order on the calling thread.
  template <class Scatter>
  AssemblyStatus evaluate(const Distribution& distribution, std::span<const double> state,
                          bool with_tangent, int threads, Scatter&& scatter) {
    AssemblyStatus status;
    const std::vector<int>& local = distribution.local_elements();
    const int n = static_cast<int>(local.size());
    const auto evaluate_one = [&](int e, Result& out) {
      const int m = materials_.of(e);
      out.rigid = m == ElementMaterials::kRigid;
      if (out.rigid) return;
      out.status = with_material(e, m, history(e), dt_, [&](const auto& material) {
        return Element::evaluate(geometry_[e], gather(dofs(e), state), material,
                                 materials_.inverse_bulk_moduli[m], internal_[e], out.r,
                                 with_tangent ? &out.K : nullptr);
      });
    };
    const auto add_one = [&](int e, const Result& out) {
      if (out.rigid) return;
      track_element(status, out.status.ok, out.status.min_J, e);
      scatter(e, out);
    };
    if (threads <= 1) {
      // One thread: each element is added while its result is still in the cache (a chunk of
      // shell tangents is 44 MB), in the same order as the chunks add them.
      chunk_.resize(std::min(n, 1));
      for (int k = 0; k < n; ++k) {
        evaluate_one(local[k], chunk_[0]);
        add_one(local[k], chunk_[0]);
      }
      return distribution.reduce(status);
    }
    chunk_.resize(std::min(n, kChunkElements));
    for (int first = 0; first < n; first += kChunkElements) {
      const int last = std::min(n, first + kChunkElements);
      std::exception_ptr error;
      // Elements differ in cost (local iterations) and the machine may be shared: small dynamic
      // batches. The model is picked per element (a jump, against microseconds of element work).
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
      for (int k = first; k < last; ++k) {
        try {
          evaluate_one(local[k], chunk_[k - first]);
        } catch (...) {
#pragma omp critical(plisse_element_loop_error)
          if (!error) error = std::current_exception();
        }
      }
      if (error) std::rethrow_exception(error);
      for (int k = first; k < last; ++k) add_one(local[k], chunk_[k - first]);
    }
    return distribution.reduce(status);
  }

  ElementMaterials materials_;
  std::vector<int> nodes_;  ///< width_ per element (nodes())
  int width_ = Element::kNodes;
  std::vector<typename Element::Geometry> geometry_;
  std::vector<typename Element::Internal> internal_, converged_internal_;
  /// Point history (material/inelastic.hpp): element e's at [history_offset_[e],
  /// history_offset_[e + 1]), kQuadPoints times its law's history_size.
  std::vector<std::size_t> history_offset_;
  std::vector<double> history_, converged_history_;
  double dt_ = 0.0;            ///< [s] see set_time_step
  std::vector<Result> chunk_;  ///< element loop buffer, kept between assemblies
};

}  // namespace plisse
