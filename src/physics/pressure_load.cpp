#include "physics/pressure_load.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "physics/cavity_volume.hpp"
#include "physics/follower_pressure.hpp"

namespace plisse {
namespace {

/// Adds the residual (loads.md, L2 or L8) and load stiffness (L3 or L9) of one face with N nodes
/// under the pressure p: the shared kernel.
template <int N>
void add_face(const Mesh& mesh, const SurfaceFace& face, double p, std::span<const double> x,
              std::span<double> residual, TangentSink* tangent) {
  std::array<int, 3 * N> dofs;
  std::array<Vec3d, N> xs;
  for (int a = 0; a < N; ++a) {
    xs[a] = mesh.nodes[face.nodes[a]];
    for (int i = 0; i < 3; ++i) {
      dofs[3 * a + i] = node_dof(face.nodes[a], i);
      xs[a][i] += x[dofs[3 * a + i]];
    }
  }
  add_follower_pressure_residual(p, xs, dofs, residual);
  if (!tangent) return;
  Eigen::Matrix<double, 3 * N, 3 * N, Eigen::RowMajor> k;
  follower_pressure_stiffness(p, xs, k);
  tangent->add(dofs, dofs, std::span<const double>(k.data(), 9 * N * N));
}

}  // namespace

bool pressure_stiffness_is_symmetric(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                     const std::vector<ConstrainedComponent>& constraints,
                                     const std::vector<CapClosure>& closures) {
  std::set<std::pair<int, int>> closed;
  for (const CapClosure& closure : closures)
    for (const auto& edge : closure.rim) closed.insert(std::minmax(edge[0], edge[1]));
  // Per corner edge: the faces it belongs to and its edge node (-1 on a linear face).
  std::map<std::pair<int, int>, std::pair<int, int>> edges;
  for (const auto& f : faces)
    for (int k = 0; k < 3; ++k) {
      const int a = f.nodes[k], b = f.nodes[(k + 1) % 3];
      auto& [count, middle] = edges[{std::min(a, b), std::max(a, b)}];
      ++count;
      middle = f.edge_node(k);
    }
  std::set<std::pair<int, int>> constrained;
  for (const auto& c : constraints) constrained.insert({c.node, c.component});
  const auto fixed = [&](int v) {
    return constrained.count({v, 0}) && constrained.count({v, 1}) && constrained.count({v, 2});
  };
  for (const auto& [edge, entry] : edges) {
    const auto [count, middle] = entry;
    if (count != 1 || closed.count(edge)) continue;  // interior edge, or a capped rim's
    // Plain ints, not a structured binding: the lambda below captures `a` (clang < 16 cannot
    // capture structured bindings).
    const int a = edge.first, b = edge.second;
    std::vector<int> nodes = {a, b};
    if (middle >= 0) nodes.push_back(middle);
    bool ok = std::all_of(nodes.begin(), nodes.end(), fixed);
    for (int k = 0; k < 3 && !ok; ++k)
      ok = std::all_of(nodes.begin(), nodes.end(), [&](int v) {
        return constrained.count({v, k}) && mesh.nodes[v][k] == mesh.nodes[a][k];
      });
    if (!ok) return false;
  }
  return true;
}

PressureLoad::PressureLoad(const Mesh& mesh, std::string name, const std::string& surface,
                           double value, Ramp ramp,
                           const std::vector<ConstrainedComponent>& constraints, int mirror_planes,
                           const std::vector<CapNodes>& caps, const InputPlace& caps_place)
    : mesh_(mesh),
      name_(std::move(name)),
      faces_(outward_faces(mesh, surface)),
      value_(value),
      ramp_(ramp) {
  WallClosure closure = close_over_caps(mesh, faces_, caps);
  for (const CapNodes& cap : caps)
    if (std::none_of(closure.caps.begin(), closure.caps.end(),
                     [&](const CapClosure& c) { return c.cap == cap.name; }))
      throw InputError(caps_place, "cap '" + cap.name + "' ties no rim of surface '" + surface +
                                       "': a cap closes a loaded surface where it ties all the "
                                       "nodes of the surface's open edges there");
  closures_ = std::move(closure.caps);
  symmetric_ = pressure_stiffness_is_symmetric(mesh, faces_, constraints, closures_);
  if (!closure.open_edge) closing_planes_ = closure.planes;
  full_body_factor_ = full_body_factor(closing_planes_.value_or(0) & mirror_planes);
}

void PressureLoad::add_couplings(std::vector<std::pair<int, int>>& pairs) const {
  for (const CapClosure& closure : closures_) add_cap_closure_couplings(closure, -1, pairs);
}

std::vector<std::string> PressureLoad::history_columns() const {
  std::vector<std::string> columns = {"pressure:" + name_};
  if (closing_planes_) columns.push_back("volume:" + name_);
  if (closing_planes_ && full_body_factor_ > 1) columns.push_back("full_volume:" + name_);
  return columns;
}

std::vector<double> PressureLoad::history_values(double t, std::span<const double> x) const {
  std::vector<double> values = {pressure(t)};
  // Positive on either side: the faces' orientation (the body's outward normal) makes a cavity
  // behind an `inner` wall positive and the inside of an `outer` one negative.
  const double v = closing_planes_ ? std::abs(closed_volume(mesh_, faces_, closures_, x)) : 0.0;
  if (closing_planes_) values.push_back(v);
  if (closing_planes_ && full_body_factor_ > 1) values.push_back(full_body_factor_ * v);
  return values;
}

void PressureLoad::assemble(double t, std::span<const double> x, std::span<double> residual,
                            TangentSink* tangent) {
  const double p = pressure(t);
  if (p == 0.0) return;
  for (const SurfaceFace& face : faces_) {
    if (face.n_nodes == 3)
      add_face<3>(mesh_, face, p, x, residual, tangent);
    else
      add_face<6>(mesh_, face, p, x, residual, tangent);
  }
  double six_volume = 0.0;
  for (const CapClosure& closure : closures_)  // (cavities.md, C16)
    add_cap_closure(mesh_, closure, p, x, residual, tangent, -1, six_volume);
}

}  // namespace plisse
