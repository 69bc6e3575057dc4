#include "physics/cap_closure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "physics/cavity_volume.hpp"
#include "physics/follower_pressure.hpp"

namespace plisse {

WallClosure close_over_caps(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                            const std::vector<CapNodes>& caps, double relative_tolerance) {
  WallClosure closure;
  std::vector<CapClosure> by_cap(caps.size());
  const auto sorted = [](int a, int b) {
    return std::array<int, 2>{std::min(a, b), std::max(a, b)};
  };
  for (const OpenEdge& edge : open_edges(mesh, faces, relative_tolerance)) {
    const auto tied = [&](const CapNodes& cap) {
      return cap.nodes.count(edge.a) && cap.nodes.count(edge.b) &&
             (edge.middle < 0 || cap.nodes.count(edge.middle));
    };
    const auto cap = edge.faces == 1 ? std::find_if(caps.begin(), caps.end(), tied) : caps.end();
    if (cap != caps.end()) {
      by_cap[cap - caps.begin()].rim.push_back({edge.a, edge.b, edge.middle});
    } else if (edge.plane >= 0) {
      closure.planes |= 1 << edge.plane;
    } else if (!closure.open_edge) {
      closure.open_edge = sorted(edge.a, edge.b);
    }
  }
  // The planes an open rim ends in, from the reference extent as open_edges measures it.
  Vec3d low = Vec3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const auto& f : faces)
    for (int v : f.node_list()) {
      low = low.cwiseMin(mesh.nodes[v]);
      high = high.cwiseMax(mesh.nodes[v]);
    }
  const double tol = faces.empty() ? 0.0 : relative_tolerance * (high - low).maxCoeff();
  for (std::size_t c = 0; c < caps.size(); ++c) {
    CapClosure& cap = by_cap[c];
    if (cap.rim.empty()) continue;
    cap.cap = caps[c].name;
    std::map<int, int> ends;  // corner -> how many rim edges end at it
    std::set<int> nodes;
    for (const auto& [a, b, middle] : cap.rim) {
      ++ends[a];
      ++ends[b];
      nodes.insert({a, b});
      if (middle >= 0) nodes.insert(middle);
    }
    cap.nodes.assign(nodes.begin(), nodes.end());
    // The planes x_k = 0 the whole rim lies in (a rim at x = 0): they hold no end of an arc.
    std::array<bool, 3> rim_plane;
    for (int k = 0; k < 3; ++k)
      rim_plane[k] = std::all_of(cap.nodes.begin(), cap.nodes.end(),
                                 [&](int v) { return std::abs(mesh.nodes[v][k]) <= tol; });
    for (const auto& [end, count] : ends) {
      if (count != 1) continue;
      const int node = end;  // a plain int: clang before 16 cannot capture a structured binding
      // An end of an open rim (a half model's arc): it must lie in a plane through the origin
      // across the rim, which the apex then lies in as well (C14).
      bool on_plane = false;
      for (int k = 0; k < 3; ++k)
        if (!rim_plane[k] && std::abs(mesh.nodes[node][k]) <= tol) {
          cap.keep[k] = 0.0;
          on_plane = true;
        }
      if (!on_plane && !closure.open_edge) {
        const auto edge = std::find_if(cap.rim.begin(), cap.rim.end(),
                                       [&](const auto& e) { return e[0] == node || e[1] == node; });
        closure.open_edge = sorted((*edge)[0], (*edge)[1]);
      }
    }
    closure.caps.push_back(std::move(cap));
  }
  return closure;
}

Vec3d closure_apex(const Mesh& mesh, const CapClosure& closure, std::span<const double> state) {
  Vec3d sum = Vec3d::Zero();
  for (int v : closure.nodes) sum += deformed_position(mesh, state, v);
  return closure.keep.cwiseProduct(sum) / static_cast<double>(closure.nodes.size());
}

namespace {

/// The cone face over rim edge (a, b, m): corners (x_c, x_b, x_a), then the edge nodes of its
/// sides (x_c + x_b)/2, x_m and (x_a + x_c)/2 (C15). kSlot[s][q]: the weight of pseudo-node q
/// (0: the apex, 1: b, 2: a, 3: m) in the face's node s.
constexpr double kSlot[6][4] = {{1, 0, 0, 0},     {0, 1, 0, 0}, {0, 0, 1, 0},
                                {0.5, 0.5, 0, 0}, {0, 0, 0, 1}, {0.5, 0, 0.5, 0}};

template <int N>
std::array<Vec3d, N> cone_face(const Vec3d& apex, const Vec3d& xa, const Vec3d& xb,
                               const Vec3d& xm) {
  if constexpr (N == 3) {
    return {apex, xb, xa};
  } else {
    return {apex, xb, xa, 0.5 * (apex + xb), xm, 0.5 * (xa + apex)};
  }
}

/// What add_cap_closure gathers over the rim's nodes (3 per node, in closure.nodes' order) and the
/// apex (the last 3), before the apex is carried to the rim's nodes.
struct PseudoBlock {
  Eigen::VectorXd force, column, row;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic> stiffness;
};

/// Adds one cone face of N nodes: its residual, border and stiffness, through kSlot, to the
/// pseudo-node rows `at` (the apex, b, a and m's first rows).
template <int N>
void add_cone_face(double p, const std::array<Vec3d, N>& ys, const std::array<int, 4>& at,
                   bool tangent, PseudoBlock& block, double& six_volume) {
  constexpr int n = 3 * N;
  std::array<int, n> local;
  std::iota(local.begin(), local.end(), 0);
  std::array<double, n> force{};
  std::array<Vec3d, N> column, row;
  if constexpr (N == 3) {
    six_volume -= ys[0].dot(ys[1].cross(ys[2]));  // (C1)
    const Vec3d c = add_follower_pressure_residual(p, ys, local, force);
    for (int s = 0; s < 3; ++s) {
      column[s] = c / 6.0;  // (C11)
      row[s] = ys[(s + 1) % 3].cross(ys[(s + 2) % 3]) / 6.0;
    }
  } else {
    six_volume -= 6.0 * quadratic_cone_volume(ys);  // (C12)
    column = add_follower_pressure_residual(p, ys, local, force);
    row = quadratic_cone_volume_gradient(ys);  // (C13)
  }
  Eigen::Matrix<double, n, n, Eigen::RowMajor> k;
  if (tangent) follower_pressure_stiffness(p, ys, k);
  for (int s = 0; s < N; ++s)
    for (int q = 0; q < 4; ++q) {
      const double w = kSlot[s][q];
      if (w == 0.0) continue;
      for (int i = 0; i < 3; ++i) {
        block.force[at[q] + i] += w * force[3 * s + i];
        block.column[at[q] + i] += w * column[s][i];
        block.row[at[q] + i] += w * row[s][i];
      }
      if (!tangent) continue;
      for (int t = 0; t < N; ++t)
        for (int r = 0; r < 4; ++r)
          if (const double v = w * kSlot[t][r]; v != 0.0)
            block.stiffness.block<3, 3>(at[q], at[r]) += v * k.template block<3, 3>(3 * s, 3 * t);
    }
}

}  // namespace

double closure_six_volume(const Mesh& mesh, const CapClosure& closure,
                          std::span<const double> state) {
  const Vec3d apex = closure_apex(mesh, closure, state);
  double six_volume = 0.0;
  for (const auto& [a, b, m] : closure.rim) {
    const Vec3d xa = deformed_position(mesh, state, a), xb = deformed_position(mesh, state, b);
    if (m < 0) {
      const auto ys = cone_face<3>(apex, xa, xb, xa);
      six_volume -= ys[0].dot(ys[1].cross(ys[2]));  // (C1)
    } else {
      six_volume -= 6.0 * quadratic_cone_volume(
                              cone_face<6>(apex, xa, xb, deformed_position(mesh, state, m)));
    }
  }
  return six_volume;
}

double closed_volume(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                     const std::vector<CapClosure>& closures, std::span<const double> state) {
  if (closures.empty()) return cavity_volume(mesh, faces, state);
  double six_volume = 6.0 * cavity_volume(mesh, faces, state);
  for (const CapClosure& closure : closures) six_volume += closure_six_volume(mesh, closure, state);
  return six_volume / 6.0;
}

void add_cap_closure(const Mesh& mesh, const CapClosure& closure, double p,
                     std::span<const double> state, std::span<double> residual,
                     TangentSink* tangent, int pressure_dof, double& six_volume) {
  const int n = static_cast<int>(closure.nodes.size());
  const int m = 3 * n;  // the rim's rows; the apex's are m, m + 1, m + 2
  const auto row_of = [&](int node) {
    return 3 * static_cast<int>(std::lower_bound(closure.nodes.begin(), closure.nodes.end(), node) -
                                closure.nodes.begin());
  };
  PseudoBlock block;
  block.force = block.column = block.row = Eigen::VectorXd::Zero(m + 3);
  if (tangent) block.stiffness = Eigen::MatrixXd::Zero(m + 3, m + 3);
  const Vec3d apex = closure_apex(mesh, closure, state);
  for (const auto& [a, b, mid] : closure.rim) {
    const Vec3d xa = deformed_position(mesh, state, a), xb = deformed_position(mesh, state, b);
    const std::array<int, 4> at = {m, row_of(b), row_of(a), mid < 0 ? -1 : row_of(mid)};
    if (mid < 0)
      add_cone_face<3>(p, cone_face<3>(apex, xa, xb, xa), at, tangent, block, six_volume);
    else
      add_cone_face<6>(p, cone_face<6>(apex, xa, xb, deformed_position(mesh, state, mid)), at,
                       tangent, block, six_volume);
  }
  // The apex is K (1/n) sum_k x_k: each rim node takes A = K / n of the apex's rows (C16).
  const Eigen::Vector3d a = closure.keep / static_cast<double>(n);
  for (int k = 0; k < n; ++k) {
    block.force.segment<3>(3 * k) += a.cwiseProduct(block.force.tail<3>());
    block.column.segment<3>(3 * k) += a.cwiseProduct(block.column.tail<3>());
    block.row.segment<3>(3 * k) += a.cwiseProduct(block.row.tail<3>());
  }
  std::vector<int> dofs(m);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < 3; ++i) dofs[3 * k + i] = node_dof(closure.nodes[k], i);
  for (int r = 0; r < m; ++r) residual[dofs[r]] += block.force[r];
  if (!tangent) return;
  // K_rim = K_rr + K_ra Abar + Abar^T K_ar + Abar^T K_aa Abar, Abar = [A A ... A] (3 x m).
  Eigen::MatrixXd abar(3, m);
  for (int k = 0; k < n; ++k) abar.block<3, 3>(0, 3 * k) = a.asDiagonal();
  const bool border = pressure_dof >= 0;
  const int size = m + (border ? 1 : 0);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> k(size, size);
  k.setZero();
  const auto& s = block.stiffness;
  k.topLeftCorner(m, m) = s.topLeftCorner(m, m) + s.topRightCorner(m, 3) * abar +
                          abar.transpose() * s.bottomLeftCorner(3, m) +
                          abar.transpose() * (s.bottomRightCorner<3, 3>() * abar);
  if (border) {
    dofs.push_back(pressure_dof);
    k.col(m).head(m) = block.column.head(m);           // d r_u / d p_c
    k.row(m).head(m) = block.row.head(m).transpose();  // d r_p / d x (C17)
  }
  tangent->add(dofs, dofs,
               std::span<const double>(k.data(), static_cast<std::size_t>(size) * size));
}

void add_cap_closure_couplings(const CapClosure& closure, int pressure_dof,
                               std::vector<std::pair<int, int>>& pairs) {
  for (int u : closure.nodes)
    for (int i = 0; i < 3; ++i) {
      for (int v : closure.nodes)
        for (int j = 0; j < 3; ++j) pairs.emplace_back(node_dof(u, i), node_dof(v, j));
      if (pressure_dof < 0) continue;
      pairs.emplace_back(pressure_dof, node_dof(u, i));
      pairs.emplace_back(node_dof(u, i), pressure_dof);
    }
}

}  // namespace plisse
