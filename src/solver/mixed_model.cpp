#include "solver/mixed_model.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "mesh/topology.hpp"
#include "solver/element_assembly.hpp"
#include "solver/mini_element.hpp"
#include "solver/node_graph.hpp"
#include "solver/petsc_call.hpp"
#include "solver/shell_element.hpp"
#include "solver/tangent_layout.hpp"
#include "solver/taylor_hood_element.hpp"
#include "solver/thread_counts.hpp"

namespace plisse {
namespace {
/// The nodes of `mesh` that are not a corner of a tetrahedron (the edge nodes of a second-order
/// mesh, and nodes no element uses), in increasing order.
std::vector<int> non_corner_nodes(const Mesh& mesh) {
  std::vector<char> corner(mesh.n_nodes(), 0);
  for (const auto& tet : mesh.tets)
    for (int v : tet) corner[v] = 1;
  std::vector<int> nodes;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (!corner[v]) nodes.push_back(v);
  return nodes;
}

/// mu / h of MixedModel::pressure_weight [N/mm^3]: mu the volume average of the deformable
/// elements' small-strain shear moduli, h the edge of the regular tetrahedron of their mean
/// volume (V = h^3 / (6 sqrt 2)). 1 when there is nothing to average (no deformable element, or
/// moduli that are not positive).
double pressure_weight_of(const Mesh& mesh, const ElementMaterials& materials) {
  double volume = 0.0, modulus_volume = 0.0;
  int counted = 0;
  for (int e = 0; e < mesh.n_tets(); ++e) {
    if (materials.rigid(e)) continue;
    const auto& tet = mesh.tets[static_cast<std::size_t>(e)];
    const double v = std::abs(six_signed_volume(mesh.nodes[tet[0]], mesh.nodes[tet[1]],
                                                mesh.nodes[tet[2]], mesh.nodes[tet[3]])) /
                     6.0;
    volume += v;
    modulus_volume +=
        v * shear_modulus(materials.materials[static_cast<std::size_t>(materials.of(e))]);
    ++counted;
  }
  if (counted == 0 || !(volume > 0.0) || !(modulus_volume > 0.0)) return 1.0;
  const double h = std::cbrt(6.0 * std::sqrt(2.0) * volume / counted);
  const double w = modulus_volume / volume / h;
  return std::isfinite(w) && w > 0.0 ? w : 1.0;
}

int count_global_unknowns(const std::vector<std::unique_ptr<ModelTerm>>& terms) {
  int n = 0;
  for (const auto& term : terms) n += term->n_global_unknowns();
  return n;
}

/// Tangent entries by full-state index into any PETSc matrix, through MatSetValues.
class EquationSink : public TangentSink {
 public:
  /// Rows outside [first, end) are someone else's (distributed runs): skipped.
  EquationSink(Mat K, const DofMap& dofs, int first, int end, std::vector<PetscInt>& scratch)
      : K_(K), dofs_(dofs), first_(first), end_(end), equations_(scratch) {}
  void add(std::span<const int> rows, std::span<const int> cols,
           std::span<const double> values) override {
    equations_.resize(rows.size() + cols.size());  // capacity kept between calls: no allocation
    for (size_t i = 0; i < rows.size(); ++i) {
      const int eq = dofs_.equation(rows[i]);
      equations_[i] = eq >= first_ && eq < end_ ? eq : -1;
    }
    for (size_t j = 0; j < cols.size(); ++j) equations_[rows.size() + j] = dofs_.equation(cols[j]);
    // Negative (constrained) indices are skipped by PETSc.
    PLISSE_PETSC(MatSetValues(K_, static_cast<PetscInt>(rows.size()), equations_.data(),
                              static_cast<PetscInt>(cols.size()), equations_.data() + rows.size(),
                              values.data(), ADD_VALUES));
  }

 private:
  Mat K_;
  const DofMap& dofs_;
  int first_, end_;
  std::vector<PetscInt>& equations_;
};
}  // namespace

bool MixedModel::symmetric() const {
  for (const auto& term : terms_)
    if (!term->symmetric()) return false;
  return true;
}

MixedModel::MixedModel(const Mesh& mesh, AnyMaterial material, double inverse_bulk_modulus,
                       std::vector<ConstrainedComponent> constraints,
                       std::vector<std::unique_ptr<ModelTerm>> terms, ElementFamily family)
    : MixedModel(mesh, ElementMaterials::uniform(std::move(material), inverse_bulk_modulus),
                 std::move(constraints), std::move(terms), family) {}

MixedModel::MixedModel(const Mesh& mesh, ElementMaterials materials,
                       std::vector<ConstrainedComponent> constraints,
                       std::vector<std::unique_ptr<ModelTerm>> terms, ElementFamily family)
    : mesh_(mesh), family_(family), constraints_(std::move(constraints)), terms_(std::move(terms)) {
  PLISSE_CHECK(mesh.order() == mesh_order_of(family),
               "the " << to_string(family) << " element needs a mesh of order "
                      << mesh_order_of(family) << ", this one has order " << mesh.order());
  pressure_weight_ = pressure_weight_of(mesh, materials);
  twins_ = family == ElementFamily::shell
               ? PressureTwins{mesh.n_nodes(), {}, {}}
               : make_pressure_twins(mesh.n_nodes(), mesh.tets, materials.pressure_region);
  // A twin carries a pressure value only: the displacement is its corner's.
  for (int k = 0; k < twins_.n_twins(); ++k)
    for (int c = 0; c < 3; ++c) constraints_.push_back({mesh.n_nodes() + k, c, 0.0, Ramp{}});
  if (family == ElementFamily::mini) {
    elements_ = std::make_unique<ElementAssembly<MiniElement>>(mesh, std::move(materials), twins_);
  } else if (family == ElementFamily::taylor_hood) {
    elements_ =
        std::make_unique<ElementAssembly<TaylorHoodElement>>(mesh, std::move(materials), twins_);
    // The pressure is linear: the edge nodes' pressure values are not unknowns.
    for (int v : non_corner_nodes(mesh)) constraints_.push_back({v, 3, 0.0, Ramp{}});
  } else {
    PLISSE_CHECK(mesh.is_shell() && mesh.shell_thickness.size() == mesh.nodes.size() &&
                     mesh.triangle_thickness.size() == mesh.triangles.size() &&
                     mesh.triangle_neighbours.size() == mesh.triangles.size() &&
                     mesh.triangle_adjacent.size() == mesh.triangles.size(),
                 "the shell element needs the mid-surface of a shell (make_shell_surface)");
    elements_ = std::make_unique<ElementAssembly<ShellElement>>(mesh, std::move(materials));
    // Plane stress eliminates the pressure inside the element (shell.md, KL9): no node has a
    // pressure unknown. The state keeps its four values per node, so that the terms, the
    // outputs and the checkpoints read one layout; held at 0, the pressure values get no
    // equation (the system would be singular in them) and no weight (pressure_weight() is 1).
    for (int v = 0; v < mesh.n_nodes(); ++v) constraints_.push_back({v, 3, 0.0, Ramp{}});
  }
  const ElementNodes element_nodes = visit_elements([](const auto& e) { return e.nodes(); });
  const int n_global = count_global_unknowns(terms_);
  int next_global = 0;
  for (auto& term : terms_) {
    // The global unknowns follow the values of every node (DofMap::global_dof).
    term->set_first_global_dof(DofMap::kPerNode * twins_.n_nodes + next_global);
    next_global += term->n_global_unknowns();
  }
  for (const auto& term : terms_) term->couplings_changed();  // what they report now is the start
  const std::vector<std::pair<int, int>> couplings = term_couplings();
  const NodeGraph graph = build_node_graph(twins_.n_nodes, element_nodes, couplings);
  distribution_ = std::make_unique<Distribution>(graph, element_nodes, n_global, constraints_);
  layout_ = std::make_unique<TangentLayout>(graph, element_nodes, *distribution_, couplings);
  state_.assign(dofs().n_dofs(), 0.0);
  full_residual_.assign(state_.size(), 0.0);
  std::vector<double> weights(state_.size(), 1.0);
  for (int d = 0; d < dofs().n_dofs(); ++d)
    if (dofs().is_pressure(d)) weights[static_cast<std::size_t>(d)] = pressure_weight_;
  equation_weights_ = create_vector();
  distribution_->owned_from_full(weights, equation_weights_);
  save_converged();
}

MixedModel::~MixedModel() { VecDestroy(&equation_weights_); }

int MixedModel::n_elements() const {
  return visit_elements([](const auto& e) { return e.n_elements(); });
}

const ElementMaterials& MixedModel::element_materials() const {
  return visit_elements([](const auto& e) -> const ElementMaterials& { return e.materials(); });
}

Vec MixedModel::create_vector() const { return distribution_->create_vector(); }

std::vector<double> MixedModel::full_from_free(Vec x) const {
  std::vector<double> full = distribution_->full_from_free(x);
  for (int d = 0; d < dofs().n_dofs(); ++d)
    if (dofs().is_pressure(d)) full[static_cast<std::size_t>(d)] *= pressure_weight_;
  return full;
}

int MixedModel::assembly_threads() const {
  return threads_ > 0 ? threads_ : default_assembly_threads();
}

void MixedModel::set_time(double t) {
  time_ = t;
  visit_elements([&](auto& e) { e.set_time_step(time_ - converged_time_); });
  for (const auto& c : constraints_) state_[DofMap::dof(c.node, c.component)] = c.at(t);
}

void MixedModel::set_external_force(std::vector<double> force, Ramp ramp) {
  PLISSE_CHECK(force.size() == state_.size(), "external force has " << force.size()
                                                                    << " entries, the model "
                                                                    << state_.size() << " dofs");
  external_force_ = std::move(force);
  external_ramp_ = ramp;
}

void MixedModel::get_free(Vec x) const {
  distribution_->owned_from_full(state_, x);
  PLISSE_PETSC(VecPointwiseDivide(x, x, equation_weights_));
}

void MixedModel::set_free(Vec x) {
  distribution_->for_each_free_value(x, [&](int d, double value) {
    state_[d] = dofs().is_pressure(d) ? pressure_weight_ * value : value;
  });
}

AssemblyStatus MixedModel::assemble_residual(Vec f) {
  std::fill(full_residual_.begin(), full_residual_.end(), 0.0);
  const AssemblyStatus status = visit_elements([&](auto& e) {
    return e.add_residual(*distribution_, state_, full_residual_, assembly_threads());
  });
  for (auto& term : terms_) term->assemble(time_, state_, full_residual_, nullptr);
  if (!external_force_.empty()) {
    const double factor = external_ramp_.factor(time_);
    for (size_t d = 0; d < full_residual_.size(); ++d)
      full_residual_[d] -= factor * external_force_[d];
  }
  distribution_->owned_from_full(full_residual_, f);
  PLISSE_PETSC(VecPointwiseMult(f, f, equation_weights_));
  return status;
}

AssemblyStatus MixedModel::assemble_tangent(Mat K) {
  AssemblyStatus status;
  // A term adds its residual and its tangent in one call (ModelTerm::assemble); the residual part
  // lands in term_residual_ and is not kept. No caller of this pass needs it: Newton's Jacobian
  // callback comes after SNES evaluated the residual at the same state (assemble_residual, with
  // the elements' part and the external force, which this pass does not compute), and the
  // stability check, the eigenmodes and the Krylov steps ask for the tangent alone. A residual
  // kept here would be the terms' part only, a second and partial copy that nothing reads.
  term_residual_.assign(state_.size(), 0.0);
  if (layout_->matches(K)) {
    // Each entry receives its element contributions in element order, then the terms', exactly
    // as MatSetValues(ADD_VALUES) would add them: the same bits.
    PetscScalar* values = layout_->open_values(K);
    status = visit_elements([&](auto& e) {
      return e.add_tangent(*distribution_, state_, *layout_, values, assembly_threads());
    });
    TangentLayout::TermSink sink(*layout_, values);
    for (auto& term : terms_) term->assemble(time_, state_, term_residual_, &sink);
    layout_->close_values(K, values);
  } else {
    PLISSE_PETSC(MatZeroEntries(K));
    status = visit_elements(
        [&](auto& e) { return e.add_tangent(*distribution_, state_, K, assembly_threads()); });
    EquationSink sink(K, dofs(), first_owned_equation(), end_owned_equation(), equations_);
    for (auto& term : terms_) term->assemble(time_, state_, term_residual_, &sink);
  }
  PLISSE_PETSC(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
  PLISSE_PETSC(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
  PLISSE_PETSC(MatDiagonalScale(K, equation_weights_, equation_weights_));
  return status;
}

Mat MixedModel::create_matrix() const { return layout_->create_matrix(symmetric()); }

bool MixedModel::update_multipliers() {
  bool again = false;
  for (auto& term : terms_) again = term->update_multipliers(state_) || again;
  return again;
}

MixedModel::Snapshot MixedModel::snapshot() const {
  Snapshot s;
  s.state = converged_state_;
  s.bubbles = visit_elements([&](const auto& e) { return e.converged_values(*distribution_); });
  for (const auto& term : terms_) s.term_states.push_back(term->save_state());
  return s;
}

void MixedModel::restore(const Snapshot& s) {
  const std::size_t n_internal =
      visit_elements([](const auto& e) { return e.n_internal_values(); });
  PLISSE_CHECK(s.state.size() == state_.size() && s.bubbles.size() == n_internal &&
                   s.term_states.size() == terms_.size(),
               "the checkpoint does not fit this model (" << s.state.size() << " values for "
                                                          << state_.size() << " dofs)");
  state_ = s.state;
  visit_elements([&](auto& e) { e.restore(s.bubbles); });
  for (size_t k = 0; k < terms_.size(); ++k) terms_[k]->load_state(s.term_states[k]);
  converged_state_ = state_;
  refresh_couplings();
}

std::size_t MixedModel::n_internal_values() const {
  return visit_elements([](const auto& e) { return e.n_internal_values(); });
}

void MixedModel::continue_from(std::span<const double> state, std::span<const double> internal) {
  const std::size_t nodal = static_cast<std::size_t>(DofMap::kPerNode) * mesh_.n_nodes();
  const std::size_t n_internal =
      visit_elements([](const auto& e) { return e.n_internal_values(); });
  PLISSE_CHECK(state.size() >= nodal && internal.size() == n_internal,
               "the earlier run's state does not fit this model ("
                   << state.size() << " values for " << nodal << " nodal values, "
                   << internal.size() << " internal for " << n_internal << ")");
  std::copy_n(state.begin(), nodal, state_.begin());
  for (int k = 0; k < twins_.n_twins(); ++k)
    state_[DofMap::dof(mesh_.n_nodes() + k, 3)] =
        state_[DofMap::dof(twins_.corner[static_cast<std::size_t>(k)], 3)];
  visit_elements([&](auto& e) { e.restore(internal); });
  set_time(time_);
  save_converged();
}

void MixedModel::resume_at(double t) {
  converged_time_ = t;
  set_time(t);
}

void MixedModel::save_converged() {
  converged_state_ = state_;
  visit_elements([&](auto& e) {
    // The points' history must be that of this state: the last assembly may have been elsewhere
    // (a line-search trial, a tangent at the previous iterate), so evaluate it here.
    if (e.has_history()) {
      history_residual_.assign(state_.size(), 0.0);
      e.add_residual(*distribution_, state_, history_residual_, assembly_threads());
    }
    e.save_converged();
  });
  converged_time_ = time_;
  visit_elements([](auto& e) { e.set_time_step(0.0); });
  for (auto& term : terms_) term->accept_step(state_);
  refresh_couplings();
}

void MixedModel::refresh_couplings() {
  bool changed = false;
  for (auto& term : terms_) changed = term->couplings_changed() || changed;
  if (!changed) return;
  // The distribution (ranks, equation numbers) was made from the first graph and stays: only
  // the pattern of the owned rows grows.
  const ElementNodes element_nodes = visit_elements([](const auto& e) { return e.nodes(); });
  const std::vector<std::pair<int, int>> couplings = term_couplings();
  const NodeGraph graph = build_node_graph(twins_.n_nodes, element_nodes, couplings);
  layout_ = std::make_unique<TangentLayout>(graph, element_nodes, *distribution_, couplings);
  ++pattern_version_;
}

std::vector<std::pair<int, int>> MixedModel::term_couplings() const {
  // (row, column) full-state dofs the terms couple, beyond the elements.
  std::vector<std::pair<int, int>> couplings;
  for (const auto& term : terms_) term->add_couplings(couplings);
  return couplings;
}

void MixedModel::restore_converged() {
  state_ = converged_state_;
  visit_elements([](auto& e) { e.restore_converged(); });
  for (auto& term : terms_) term->reject_step();
}

double MixedModel::local_reaction(int node, int k) const {
  // The residual is complete on the owned nodes only; on a free component it is not a reaction.
  const int dof = DofMap::dof(node, k);
  return distribution_->owns_node(node) && dofs().equation(dof) < 0 ? full_residual_[dof] : 0.0;
}

Vec3d MixedModel::reaction(const std::vector<int>& triangles) const {
  return node_reaction(triangle_nodes(mesh_, triangles));
}

Vec3d MixedModel::node_reaction(const std::set<int>& nodes) const {
  Vec3d force = Vec3d::Zero();
  for (int v : nodes)
    for (int k = 0; k < 3; ++k) force[k] += local_reaction(v, k);
  distribution_->sum_over_ranks(force.data(), 3);
  return force;
}

Vec3d MixedModel::node_reaction_moment(const std::set<int>& nodes) const {
  Vec3d moment = Vec3d::Zero();
  for (int v : nodes) {
    const Vec3d f(local_reaction(v, 0), local_reaction(v, 1), local_reaction(v, 2));
    if (f.isZero(0.0)) continue;  // free, or not this rank's
    Vec3d x = mesh_.nodes[static_cast<std::size_t>(v)];
    for (int k = 0; k < 3; ++k) x[k] += state_[static_cast<std::size_t>(DofMap::dof(v, k))];
    moment += x.cross(f);
  }
  distribution_->sum_over_ranks(moment.data(), 3);
  return moment;
}

std::vector<double> MixedModel::nodal_reactions() const {
  std::vector<double> reactions(3 * static_cast<std::size_t>(mesh_.n_nodes()), 0.0);
  for (int v = 0; v < mesh_.n_nodes(); ++v)
    for (int k = 0; k < 3; ++k)
      reactions[3 * static_cast<std::size_t>(v) + k] = local_reaction(v, k);
  distribution_->sum_over_ranks(reactions.data(), reactions.size());
  return reactions;
}

std::vector<Mat3d> MixedModel::element_deformation_gradients() const {
  std::vector<Mat3d> F(static_cast<std::size_t>(n_elements()), Mat3d::Identity());
  visit_elements([&](const auto& elements) {
    elements.for_each_deformation(mesh_, state_, [&](int e, double V0, const Mat3d& F_integral) {
      F[static_cast<std::size_t>(e)] = F_integral / V0;
    });
  });
  return F;
}

std::vector<ElementFields> MixedModel::element_fields() const {
  return visit_elements(
      [&](const auto& e) { return e.fields(*distribution_, state_, assembly_threads()); });
}

std::vector<double> MixedModel::nodal_pressures() const {
  std::vector<double> p(mesh_.n_nodes());
  for (int v = 0; v < mesh_.n_nodes(); ++v) p[v] = state_[DofMap::dof(v, 3)];
  if (family_ == ElementFamily::taylor_hood)
    for (int e = 0; e < mesh_.n_tets(); ++e)
      for (int k = 0; k < 6; ++k) {
        const auto [i, j] = kTetEdges[k];
        p[mesh_.tet_edge_nodes[e][k]] = 0.5 * (p[mesh_.tets[e][i]] + p[mesh_.tets[e][j]]);
      }
  return p;
}

double MixedModel::element_pressure(int e, int node) const {
  if (family_ == ElementFamily::shell) return 0.0;  // plane stress: no pressure unknowns
  const auto& corners = mesh_.tets[static_cast<std::size_t>(e)];
  const auto corner_pressure = [&](int a) {
    const int carrier = twins_.carrier_of(e, a, corners[static_cast<std::size_t>(a)]);
    return state_[DofMap::dof(carrier, 3)];
  };
  for (int a = 0; a < 4; ++a)
    if (corners[static_cast<std::size_t>(a)] == node) return corner_pressure(a);
  PLISSE_CHECK(mesh_.order() == 2, "node " << node << " is not a corner of element " << e);
  for (int k = 0; k < 6; ++k)
    if (mesh_.tet_edge_nodes[static_cast<std::size_t>(e)][static_cast<std::size_t>(k)] == node) {
      const auto [i, j] = kTetEdges[static_cast<std::size_t>(k)];
      return 0.5 * (corner_pressure(i) + corner_pressure(j));
    }
  PLISSE_CHECK(false, "node " << node << " is not a node of element " << e);
  return 0.0;
}

double MixedModel::strain_energy() const {
  return visit_elements([&](const auto& e) { return e.strain_energy(*distribution_, state_); });
}

std::vector<shell::ShellOutputs> MixedModel::shell_outputs() const {
  const auto* shells = std::get_if<std::unique_ptr<ElementAssembly<ShellElement>>>(&elements_);
  if (shells == nullptr) return {};
  return (*shells)->per_element(
      *distribution_, state_, assembly_threads(), shell::zero_shell_outputs(),
      [](const auto& geometry, const auto& x, const auto& material, double inverse_bulk_modulus,
         const auto& /*internal*/) {
        return ShellElement::outputs(geometry, x, material, inverse_bulk_modulus);
      });
}

BodyAverages MixedModel::averages() const { return averages(element_fields()); }

BodyAverages MixedModel::averages(const std::vector<ElementFields>& fields) const {
  PLISSE_CHECK(
      fields.size() == static_cast<std::size_t>(n_elements()),
      "averages: " << fields.size() << " element fields for " << n_elements() << " elements");
  BodyAverages avg;
  avg.F.setZero();
  double reference_volume = 0.0;
  visit_elements([&](const auto& elements) {
    elements.for_each_deformation(mesh_, state_, [&](int e, double V0, const Mat3d& F_integral) {
      avg.F += F_integral;
      const double v = fields[e].J * V0;
      avg.cauchy += v * fields[e].cauchy;
      avg.volume += v;
      reference_volume += V0;
    });
  });
  avg.F /= reference_volume;
  if (avg.volume > 0) avg.cauchy /= avg.volume;
  return avg;
}

}  // namespace plisse
