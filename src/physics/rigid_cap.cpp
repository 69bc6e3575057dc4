#include "physics/rigid_cap.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "core/error.hpp"
#include "mesh/topology.hpp"
#include "physics/cavity_volume.hpp"
#include "physics/rotation.hpp"

namespace plisse {

RigidCap::RigidCap(const Cap& cap, const Mesh& mesh,
                   const std::vector<ConstrainedComponent>& constraints)
    : mesh_(mesh), settings_(cap) {
  // A solid's surface tag; on a shell an edge tag (its rim) or a face tag (caps.md, G8).
  const std::set<int> nodes = condition_nodes(mesh, cap.surface);
  if (cap.point) {
    point_ = *cap.point;
  } else {
    point_ = Vec3d::Zero();
    for (int v : nodes) point_ += mesh.nodes[v];
    point_ /= static_cast<double>(nodes.size());
  }
  std::set<std::pair<int, int>> constrained;
  for (const auto& c : constraints) constrained.insert({c.node, c.component});
  for (int v : nodes) {
    const std::size_t before = ties_.size();
    for (int i = 0; i < 3; ++i)
      if (!constrained.count({v, i})) ties_.push_back({v, i});
    if (ties_.size() == before) continue;
    nodes_.push_back(v);
    first_tie_.push_back(static_cast<int>(before));
  }
  first_tie_.push_back(static_cast<int>(ties_.size()));
  if (ties_.empty())
    throw InputError(cap.place, "cap '" + cap.name +
                                    "': every component of its nodes is already prescribed by "
                                    "the boundary conditions: nothing to tie");
  for (int m = 0; m < 6; ++m) {
    const auto& given = m < 3 ? settings_.displacement[m] : settings_.rotation[m - 3];
    free_index_[m] = given ? -1 : n_free_++;
  }
  if (mesh.is_shell()) refuse_free_turn_about_a_line(nodes);
}

std::vector<RigidHold> RigidCap::rigid_holds(double /*t*/) const {
  std::vector<RigidHold> holds;
  if (n_free_ == 0) {
    for (const Tie& tie : ties_)
      holds.push_back({{tie.node}, mesh_.nodes[tie.node], Vec3d::Unit(tie.component), false});
    return holds;
  }
  for (int m = 0; m < 6; ++m)
    if (free_index_[m] < 0) holds.push_back({nodes_, point_, Vec3d::Unit(m % 3), m >= 3});
  if (holds.empty()) holds.push_back({nodes_, point_, Vec3d::Zero(), false});
  return holds;
}

void RigidCap::refuse_free_turn_about_a_line(const std::set<int>& nodes) const {
  // The nodes' principal direction: the largest eigenvector of their scatter. They lie on a line
  // when the other two spreads are round-off against it.
  Vec3d mean = Vec3d::Zero();
  for (int v : nodes) mean += mesh_.nodes[v];
  mean /= static_cast<double>(nodes.size());
  Mat3d scatter = Mat3d::Zero();
  for (int v : nodes) {
    const Vec3d r = mesh_.nodes[v] - mean;
    scatter += r * r.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Mat3d> eigen(scatter);
  const double largest = eigen.eigenvalues()(2);
  if (largest > 0.0 && eigen.eigenvalues()(1) > 1e-16 * largest) return;  // not on one line
  const Vec3d d = eigen.eigenvectors().col(2);
  // The turn about d is held when a prescribed rotation component has a share of d.
  for (int k = 0; k < 3; ++k)
    if (settings_.rotation[k] && std::abs(d[k]) > 1e-9) return;
  char text[400];
  std::snprintf(text, sizeof text,
                "cap '%s' holds the nodes of a shell's edge, not the wall's slope (a hinge, "
                "docs/theory/caps.md, G8), and its %zu nodes lie on one line along [%.4g, %.4g, "
                "%.4g]: nothing holds the cap's turn about that line, so the tangent is singular; "
                "prescribe that rotation (`rotation`), or clamp the edge instead of capping it",
                settings_.name.c_str(), nodes.size(), d.x(), d.y(), d.z());
  throw InputError(settings_.place, text);
}

int RigidCap::n_global_unknowns() const { return n_ties() + n_free_; }

std::array<double, 6> RigidCap::motion(double t, std::span<const double> x) const {
  const double factor = settings_.ramp.factor(t);
  std::array<double, 6> q{};
  for (int m = 0; m < 6; ++m) {
    const auto& given = m < 3 ? settings_.displacement[m] : settings_.rotation[m - 3];
    q[m] = given ? factor * *given : x[motion_dof(m)];
  }
  return q;
}

void RigidCap::add_couplings(std::vector<std::pair<int, int>>& pairs) const {
  for (int k = 0; k < n_ties(); ++k) {
    const int l = multiplier_dof(k), u = node_dof(ties_[k].node, ties_[k].component);
    pairs.emplace_back(l, u);
    pairs.emplace_back(u, l);
    pairs.emplace_back(l, l);
    for (int m = 0; m < 6; ++m)
      if (const int q = motion_dof(m); q >= 0) {
        pairs.emplace_back(l, q);
        pairs.emplace_back(q, l);
      }
  }
  for (int m = 0; m < 6; ++m)
    for (int n = 0; n < 6; ++n)
      if (motion_dof(m) >= 0 && motion_dof(n) >= 0)
        pairs.emplace_back(motion_dof(m), motion_dof(n));
}

void RigidCap::assemble(double t, std::span<const double> x, std::span<double> residual,
                        TangentSink* tangent) {
  const std::array<double, 6> q = motion(t, x);
  const Vec3d u_c(q[0], q[1], q[2]), theta(q[3], q[4], q[5]);
  // A Newton iterate far off (a step past a limit load): the step is cut back for this reason,
  // which names the cap rather than the rotation formula's range.
  if (!(theta.norm() <= kMaxRotationAngle)) {
    char text[96];
    std::snprintf(text, sizeof text, "%.3g", theta.norm());
    throw Error("the Newton iterations diverged: they turned cap '" + settings_.name + "' by " +
                text + " rad, more than the 2 pi a rotation vector describes");
  }
  const double factor = settings_.ramp.factor(t);
  Mat3d theta_theta = Mat3d::Zero();  // −Σ λ_a,i ∂²(R d_a)_i/∂θ∂θ   (G7)
  Vec3d force_on_cap = Vec3d::Zero(), moment_rows = Vec3d::Zero();
  for (std::size_t j = 0; j < nodes_.size(); ++j) {
    const int v = nodes_[j];
    const Vec3d d = mesh_.nodes[v] - point_;
    const RotatedVector w = rotate(theta, d);
    // g = x_a − (X_c + u_c) − R d   (G4)
    Vec3d g;
    for (int i = 0; i < 3; ++i) g[i] = d[i] + x[node_dof(v, i)] - u_c[i] - w.value[i];
    for (int k = first_tie_[j]; k < first_tie_[j + 1]; ++k) {
      const int i = ties_[k].component, l = multiplier_dof(k), u = node_dof(v, i);
      const double lambda = x[l];
      residual[u] += lambda;  // (G5)
      residual[l] += g[i];
      force_on_cap[i] += lambda;
      moment_rows += lambda * w.jacobian.row(i).transpose();
      theta_theta -= lambda * w.hessian[i];
      if (!tangent) continue;
      const double one = 1.0;
      tangent->add({&u, 1}, {&l, 1}, {&one, 1});
      tangent->add({&l, 1}, {&u, 1}, {&one, 1});
      for (int m = 0; m < 6; ++m) {
        const int dof = motion_dof(m);
        if (dof < 0) continue;
        // ∂g_i/∂u_c = −e_i, ∂g_i/∂θ = −J_i   (G5), and the transposed entry of row m
        const double entry = m < 3 ? -(i == m ? 1.0 : 0.0) : -w.jacobian(i, m - 3);
        if (entry == 0.0) continue;
        tangent->add({&l, 1}, {&dof, 1}, {&entry, 1});
        tangent->add({&dof, 1}, {&l, 1}, {&entry, 1});
      }
    }
  }
  // Rows of the free motions: −Σ λ − F and −Σ J^T λ − M   (G6)
  for (int m = 0; m < 6; ++m) {
    const int dof = motion_dof(m);
    if (dof < 0) continue;
    residual[dof] += m < 3 ? -force_on_cap[m] - factor * settings_.force[m]
                           : -moment_rows[m - 3] - factor * settings_.moment[m - 3];
    if (!tangent || m < 3) continue;
    for (int n = 3; n < 6; ++n) {
      const int other = motion_dof(n);
      if (other < 0) continue;
      const double entry = theta_theta(m - 3, n - 3);
      tangent->add({&dof, 1}, {&other, 1}, {&entry, 1});
    }
  }
}

std::vector<std::string> RigidCap::history_columns() const {
  std::vector<std::string> out;
  for (const char* prefix : {"force_", "moment_", "u", "r"})
    for (const char* axis : {"x", "y", "z"})
      out.push_back(std::string(prefix) + axis + ":" + settings_.name);
  return out;
}

std::vector<double> RigidCap::history_values(double t, std::span<const double> x) const {
  const std::array<double, 6> q = motion(t, x);
  const Vec3d centre = point_ + Vec3d(q[0], q[1], q[2]);
  Vec3d force = Vec3d::Zero(), moment = Vec3d::Zero();
  for (std::size_t j = 0; j < nodes_.size(); ++j) {
    const int v = nodes_[j];
    Vec3d on_body = Vec3d::Zero();  // the cap's force on the node: −λ   (G5)
    for (int k = first_tie_[j]; k < first_tie_[j + 1]; ++k)
      on_body[ties_[k].component] = -x[multiplier_dof(k)];
    force += on_body;
    moment += (deformed_position(mesh_, x, v) - centre).cross(on_body);
  }
  return {force.x(), force.y(), force.z(), moment.x(), moment.y(), moment.z(),
          q[0],      q[1],      q[2],      q[3],       q[4],       q[5]};
}

}  // namespace plisse
