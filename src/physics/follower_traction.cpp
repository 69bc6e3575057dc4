#include "physics/follower_traction.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "physics/cavity_volume.hpp"
#include "physics/pressure_load.hpp"
#include "physics/quadratic_triangle.hpp"

namespace plisse {
namespace {

/// The centroid rule of a 3-node face in the layout of the 6-node rule points: exact for the
/// constant a of a flat triangle.
const quadratic_triangle::RulePoint& linear_centroid() {
  static const quadratic_triangle::RulePoint point{{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 0.0, 0.0, 0.0},
                                                   {-1.0, 1.0, 0.0, 0.0, 0.0, 0.0},
                                                   {-1.0, 0.0, 1.0, 0.0, 0.0, 0.0},
                                                   0.5};
  return point;
}

}  // namespace

void follower_traction_face(const FollowerTractionValues& v, double factor,
                            std::span<const Vec3d> xs, std::span<double> f, double* k) {
  const int n = static_cast<int>(xs.size());
  PLISSE_ASSERT(n == 3 || n == 6);
  const double sigma = factor * v.normal, tau = factor * v.shear;
  std::fill(f.begin(), f.begin() + 3 * n, 0.0);
  if (k) std::fill(k, k + 9 * n * n, 0.0);
  const auto add_point = [&](const quadratic_triangle::RulePoint& q) {
    Vec3d x_xi = Vec3d::Zero(), x_eta = Vec3d::Zero();
    for (int b = 0; b < n; ++b) {
      x_xi += q.dN_dxi[b] * xs[b];
      x_eta += q.dN_deta[b] * xs[b];
    }
    const Vec3d a = x_xi.cross(x_eta);  // n da = a dξ dη
    const double area = a.norm();
    Vec3d g = sigma * a;                  // force per unit reference area of the face map   (L14)
    Mat3d G = sigma * Mat3d::Identity();  // dg/da                             (L15)
    if (tau != 0.0 && area > 0.0) {
      const Vec3d normal = a / area;
      const double c = v.direction.dot(normal);
      const double m = std::sqrt(std::max(0.0, 1.0 - c * c));
      if (m > kShearDirectionTolerance) {  // (L16)
        const Vec3d s = (v.direction - c * normal) / m;
        const Vec3d t = normal.cross(s);
        g += tau * area * s;
        // d(|a| s)/da = s n^T − n s^T − (c/m) t t^T
        G += tau * (s * normal.transpose() - normal * s.transpose() - (c / m) * t * t.transpose());
      }
    }
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < 3; ++r) f[3 * i + r] += q.weight * q.N[i] * g[r];
    if (!k) return;
    for (int b = 0; b < n; ++b) {
      // ∂a/∂x_b = N_b,η [x_ξ]× − N_b,ξ [x_η]×
      const Mat3d da = q.dN_deta[b] * cross_matrix(x_xi) - q.dN_dxi[b] * cross_matrix(x_eta);
      const Mat3d Gda = G * da;
      for (int i = 0; i < n; ++i)
        for (int r = 0; r < 3; ++r)
          for (int s = 0; s < 3; ++s)
            k[(3 * i + r) * 3 * n + 3 * b + s] += q.weight * q.N[i] * Gda(r, s);
    }
  };
  if (n == 3) {
    add_point(linear_centroid());
  } else {
    for (const auto& q : quadratic_triangle::rule_points()) add_point(q);
  }
}

FollowerTraction::FollowerTraction(const Mesh& mesh, std::string name, const std::string& surface,
                                   const FollowerTractionValues& values, Ramp ramp,
                                   const std::vector<ConstrainedComponent>& constraints)
    : mesh_(mesh),
      name_(std::move(name)),
      faces_(outward_faces(mesh, surface)),
      values_(values),
      ramp_(ramp),
      symmetric_(values.shear == 0.0 &&
                 pressure_stiffness_is_symmetric(mesh, faces_, constraints)) {
  const std::set<int> nodes = surface_nodes(faces_);
  nodes_.assign(nodes.begin(), nodes.end());
  for (const SurfaceFace& face : faces_)
    for (int v : face.node_list())
      face_node_index_.push_back(
          static_cast<int>(std::lower_bound(nodes_.begin(), nodes_.end(), v) - nodes_.begin()));
  u_accepted_.assign(nodes_.size(), Vec3d::Zero());
  f_accepted_.assign(nodes_.size(), Vec3d::Zero());
}

void FollowerTraction::assemble(double t, std::span<const double> x, std::span<double> residual,
                                TangentSink* tangent) {
  t_current_ = t;
  const double factor = ramp_.factor(t);
  std::array<Vec3d, 6> xs;
  std::array<int, 18> dofs;
  std::array<double, 18> f;
  std::array<double, 324> k;
  for (const SurfaceFace& face : faces_) {
    const int n = face.n_nodes;
    for (int a = 0; a < n; ++a) {
      xs[a] = mesh_.nodes[face.nodes[a]];
      for (int i = 0; i < 3; ++i) {
        dofs[3 * a + i] = node_dof(face.nodes[a], i);
        xs[a][i] += x[dofs[3 * a + i]];
      }
    }
    follower_traction_face(values_, factor, {xs.data(), static_cast<std::size_t>(n)}, f,
                           tangent ? k.data() : nullptr);
    for (int j = 0; j < 3 * n; ++j) residual[dofs[j]] -= f[j];  // residual = internal − external
    if (!tangent) continue;
    for (int j = 0; j < 9 * n * n; ++j) k[j] = -k[j];
    tangent->add({dofs.data(), static_cast<std::size_t>(3 * n)},
                 {dofs.data(), static_cast<std::size_t>(3 * n)},
                 {k.data(), static_cast<std::size_t>(9 * n * n)});
  }
}

std::vector<Vec3d> FollowerTraction::nodal_forces(double t, std::span<const double> x) const {
  std::vector<Vec3d> out(nodes_.size(), Vec3d::Zero());
  const double factor = ramp_.factor(t);
  std::array<Vec3d, 6> xs;
  std::array<double, 18> f;
  std::size_t index = 0;
  for (const SurfaceFace& face : faces_) {
    const int n = face.n_nodes;
    for (int a = 0; a < n; ++a) xs[a] = deformed_position(mesh_, x, face.nodes[a]);
    follower_traction_face(values_, factor, {xs.data(), static_cast<std::size_t>(n)}, f, nullptr);
    for (int a = 0; a < n; ++a)
      out[face_node_index_[index++]] += Vec3d(f[3 * a], f[3 * a + 1], f[3 * a + 2]);
  }
  return out;
}

double FollowerTraction::work(const std::vector<Vec3d>& forces, std::span<const double> x) const {
  double w = work_;
  for (std::size_t j = 0; j < nodes_.size(); ++j) {
    const int v = nodes_[j];
    const Vec3d u(x[node_dof(v, 0)], x[node_dof(v, 1)], x[node_dof(v, 2)]);
    w += 0.5 * (f_accepted_[j] + forces[j]).dot(u - u_accepted_[j]);  // (L16)
  }
  return w;
}

void FollowerTraction::accept_step(std::span<const double> x) {
  std::vector<Vec3d> forces = nodal_forces(t_current_, x);
  work_ = work(forces, x);
  f_accepted_ = std::move(forces);
  for (std::size_t j = 0; j < nodes_.size(); ++j)
    for (int i = 0; i < 3; ++i) u_accepted_[j][i] = x[node_dof(nodes_[j], i)];
  t_accepted_ = t_current_;
}

std::vector<double> FollowerTraction::save_state() const {
  std::vector<double> state = {t_accepted_, work_};
  for (std::size_t j = 0; j < nodes_.size(); ++j)
    state.insert(state.end(), {u_accepted_[j].x(), u_accepted_[j].y(), u_accepted_[j].z(),
                               f_accepted_[j].x(), f_accepted_[j].y(), f_accepted_[j].z()});
  return state;
}

void FollowerTraction::load_state(std::span<const double> state) {
  const std::size_t expected = 2 + 6 * nodes_.size();
  PLISSE_CHECK(state.size() == expected, "load '" << name_ << "': checkpoint state has "
                                                  << state.size() << " values, expected "
                                                  << expected);
  for (double v : state)
    PLISSE_CHECK(std::isfinite(v), "load '" << name_ << "': checkpoint state is not finite");
  t_accepted_ = t_current_ = state[0];
  work_ = state[1];
  for (std::size_t j = 0; j < nodes_.size(); ++j) {
    const double* s = &state[2 + 6 * j];
    u_accepted_[j] = Vec3d(s[0], s[1], s[2]);
    f_accepted_[j] = Vec3d(s[3], s[4], s[5]);
  }
}

std::vector<std::string> FollowerTraction::history_columns() const {
  return {"load_x:" + name_, "load_y:" + name_, "load_z:" + name_, "work:" + name_};
}

std::vector<double> FollowerTraction::history_values(double t, std::span<const double> x) const {
  const std::vector<Vec3d> forces = nodal_forces(t, x);
  Vec3d total = Vec3d::Zero();
  for (const Vec3d& f : forces) total += f;
  return {total.x(), total.y(), total.z(), work(forces, x)};
}

}  // namespace plisse
