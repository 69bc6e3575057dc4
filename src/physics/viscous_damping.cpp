#include "physics/viscous_damping.hpp"

#include <array>
#include <cmath>

#include "core/error.hpp"
#include "element/taylor_hood_geometry.hpp"
#include "mesh/topology.hpp"
#include "physics/body_force.hpp"
#include "physics/die_surface.hpp"

namespace plisse {
namespace {

/// Full-state index of displacement component j = 3 i + k (node i, component k).
std::size_t state_index(std::size_t j) {
  return static_cast<std::size_t>(node_dof(static_cast<int>(j / 3), static_cast<int>(j % 3)));
}

}  // namespace

double mean_edge_length(const Mesh& mesh) {
  if (mesh.is_shell()) return mean_edge_length(mesh, mesh.triangles);  // its triangles'
  PLISSE_CHECK(!mesh.tets.empty(), "mean edge length: the mesh has no tetrahedra");
  double sum = 0.0;
  for (const auto& tet : mesh.tets)
    for (const auto& e : kTetEdges)
      sum += (mesh.nodes[static_cast<std::size_t>(tet[static_cast<std::size_t>(e[0])])] -
              mesh.nodes[static_cast<std::size_t>(tet[static_cast<std::size_t>(e[1])])])
                 .norm();
  return sum / (6.0 * static_cast<double>(mesh.tets.size()));
}

namespace {

/// Calls add(node, V) with the lumped volume V [mm^3] of every node of every tetrahedron
/// (viscous.md, Z1 and Z5), element by element, or of every node of a shell (Z6).
template <class Add>
void for_each_lumped_volume(const Mesh& mesh, Add&& add) {
  if (mesh.is_shell()) {
    // A_T t_T / 3 per corner (Z6): a shell's consistent nodal volumes, the weights of its body
    // forces too (loads.md, L6s).
    const std::vector<double> volume = consistent_nodal_volumes(mesh);
    for (std::size_t v = 0; v < volume.size(); ++v) add(static_cast<int>(v), volume[v]);
    return;
  }
  if (mesh.order() == 1) {
    for (const auto& tet : mesh.tets) {
      const double quarter = six_signed_volume(mesh.nodes[static_cast<std::size_t>(tet[0])],
                                               mesh.nodes[static_cast<std::size_t>(tet[1])],
                                               mesh.nodes[static_cast<std::size_t>(tet[2])],
                                               mesh.nodes[static_cast<std::size_t>(tet[3])]) /
                             24.0;  // V_e / 4
      for (int v : tet) add(v, quarter);
    }
    return;
  }
  namespace th = taylor_hood;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    std::array<int, th::kNodes> nodes;
    std::array<Vec3d, th::kNodes> X;
    for (std::size_t a = 0; a < th::kNodes; ++a) {
      nodes[a] = a < th::kCorners ? mesh.tets[t][a] : mesh.tet_edge_nodes[t][a - th::kCorners];
      X[a] = mesh.nodes[static_cast<std::size_t>(nodes[a])];
    }
    // (viscous.md, Z5): V_a = V_e m_a / Σ_b m_b with m_a = ∫ N_a² dV (the row sums ∫ N_a dV
    // would give the corners -V_e / 20, a negative damping).
    const th::Geometry g = th::compute_geometry(X);
    std::array<double, th::kNodes> m{};
    for (std::size_t q = 0; q < th::kQuadPoints; ++q) {
      const auto N = th::shape_values(th::kQuadrature.points[q]);
      for (std::size_t a = 0; a < th::kNodes; ++a) m[a] += g.weight[q] * N[a] * N[a];
    }
    double sum = 0.0;
    for (double v : m) sum += v;
    for (std::size_t a = 0; a < th::kNodes; ++a) add(nodes[a], g.volume * m[a] / sum);
  }
}

}  // namespace

ViscousDamping::ViscousDamping(const Mesh& mesh, double viscosity, double length,
                               const std::vector<ConstrainedComponent>& constraints)
    : coefficient_(3 * mesh.nodes.size(), 0.0), u_accepted_(3 * mesh.nodes.size(), 0.0) {
  PLISSE_CHECK(
      std::isfinite(viscosity) && viscosity > 0.0,
      "viscous stabilisation: viscosity must be finite and > 0 (got " << viscosity << " MPa s)");
  PLISSE_CHECK(std::isfinite(length) && length > 0.0,
               "viscous stabilisation: length must be finite and > 0 (got " << length << " mm)");
  const double scale = viscosity / (length * length);
  for_each_lumped_volume(mesh, [&](int v, double volume) {
    for (std::size_t k = 0; k < 3; ++k)
      coefficient_[3 * static_cast<std::size_t>(v) + k] += scale * volume;
  });
  for (const ConstrainedComponent& c : constraints) {
    PLISSE_CHECK(c.node >= 0 && static_cast<std::size_t>(c.node) < mesh.nodes.size() &&
                     c.component >= 0 && c.component < 3,
                 "viscous stabilisation: constraint on node " << c.node << ", component "
                                                              << c.component << " does not exist");
    coefficient_[3 * static_cast<std::size_t>(c.node) + static_cast<std::size_t>(c.component)] =
        0.0;
  }
}

void ViscousDamping::assemble(double t, std::span<const double> x, std::span<double> residual,
                              TangentSink* tangent) {
  t_current_ = t;
  const double dt = t - t_accepted_;
  if (!(dt > 0.0)) return;
  for (std::size_t j = 0; j < coefficient_.size(); ++j) {
    const double c = coefficient_[j] / dt;  // (Z2)
    if (c == 0.0) continue;                 // constrained, or a node of no element
    const std::size_t dof = state_index(j);
    residual[dof] += c * (x[dof] - u_accepted_[j]);  // (Z1)
    if (tangent != nullptr) {
      const std::array<int, 1> index = {static_cast<int>(dof)};
      const std::array<double, 1> value = {c};
      tangent->add(index, index, value);
    }
  }
}

double ViscousDamping::step_work(std::span<const double> x, double dt) const {
  double work = 0.0;
  for (std::size_t j = 0; j < coefficient_.size(); ++j) {
    const double du = x[state_index(j)] - u_accepted_[j];
    work += coefficient_[j] / dt * du * du;  // F_j Δu_j = c_j Δu_j² / Δt
  }
  return work;
}

void ViscousDamping::accept_step(std::span<const double> x) {
  const double dt = t_current_ - t_accepted_;
  if (dt > 0.0) dissipated_energy_ += step_work(x, dt);  // (Z3)
  for (std::size_t j = 0; j < u_accepted_.size(); ++j) u_accepted_[j] = x[state_index(j)];
  t_accepted_ = t_current_;
}

std::vector<double> ViscousDamping::save_state() const {
  std::vector<double> state;
  state.reserve(2 + u_accepted_.size());
  state.push_back(t_accepted_);
  state.push_back(dissipated_energy_);
  state.insert(state.end(), u_accepted_.begin(), u_accepted_.end());
  return state;
}

void ViscousDamping::load_state(std::span<const double> state) {
  PLISSE_CHECK(state.size() == 2 + u_accepted_.size(),
               "viscous stabilisation: checkpoint state has "
                   << state.size() << " values, expected " << 2 + u_accepted_.size() << " (t, D, "
                   << u_accepted_.size() / 3 << " nodal displacements)");
  for (double v : state)
    PLISSE_CHECK(std::isfinite(v), "viscous stabilisation: checkpoint state is not finite");
  t_accepted_ = state[0];
  t_current_ = state[0];
  dissipated_energy_ = state[1];
  std::copy(state.begin() + 2, state.end(), u_accepted_.begin());
}

std::vector<std::string> ViscousDamping::history_columns() const { return {"dissipated_energy"}; }

std::vector<double> ViscousDamping::history_values(double, std::span<const double>) const {
  return {dissipated_energy_};
}

}  // namespace plisse
