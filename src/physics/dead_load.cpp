#include "physics/dead_load.hpp"

#include <cmath>
#include <map>

#include "core/error.hpp"
#include "physics/quadratic_triangle.hpp"

namespace plisse {

std::vector<std::pair<int, double>> consistent_nodal_areas(const Mesh& mesh,
                                                           const std::vector<SurfaceFace>& faces) {
  std::map<int, double> area;
  for (const SurfaceFace& face : faces) {
    if (face.n_nodes == 3) {
      const Vec3d& X0 = mesh.nodes[face.nodes[0]];
      const double third =
          (mesh.nodes[face.nodes[1]] - X0).cross(mesh.nodes[face.nodes[2]] - X0).norm() / 6.0;
      for (int a = 0; a < 3; ++a) area[face.nodes[a]] += third;  // (loads.md, L11)
      continue;
    }
    namespace qt = quadratic_triangle;
    std::array<Vec3d, qt::kNodes> X;
    for (int a = 0; a < qt::kNodes; ++a) X[a] = mesh.nodes[face.nodes[a]];
    for (const qt::RulePoint& q : qt::rule_points()) {
      const qt::FaceFrame f = qt::face_frame(X, q);
      const double dA = q.weight * f.x_xi.cross(f.x_eta).norm();  // (L11)
      for (int a = 0; a < qt::kNodes; ++a) area[face.nodes[a]] += q.N[a] * dA;
    }
  }
  return {area.begin(), area.end()};
}

std::vector<NodalForce> traction_forces(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                        const Vec3d& traction) {
  std::vector<NodalForce> out;
  for (const auto& [node, area] : consistent_nodal_areas(mesh, faces))
    out.push_back({node, area * traction});
  return out;
}

std::vector<NodalForce> total_force(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                    const Vec3d& force) {
  const auto areas = consistent_nodal_areas(mesh, faces);
  double total = 0.0;
  for (const auto& entry : areas) total += entry.second;
  PLISSE_CHECK(total > 0.0, "the loaded surface has no area (" << faces.size() << " faces)");
  std::vector<NodalForce> out;
  for (const auto& [node, area] : areas) out.push_back({node, (area / total) * force});  // (L12)
  return out;
}

DeadLoad::DeadLoad(std::string name, std::vector<NodalForce> forces, Ramp ramp)
    : name_(std::move(name)), forces_(std::move(forces)), ramp_(ramp) {
  for (const NodalForce& f : forces_) total_ += f.force;
}

void DeadLoad::assemble(double t, std::span<const double>, std::span<double> residual,
                        TangentSink*) {
  t_current_ = t;
  const double factor = ramp_.factor(t);
  for (const NodalForce& f : forces_)
    for (int i = 0; i < 3; ++i) residual[node_dof(f.node, i)] -= factor * f.force[i];
}

double DeadLoad::projected_displacement(std::span<const double> x) const {
  double s = 0.0;
  for (const NodalForce& f : forces_)
    for (int i = 0; i < 3; ++i) s += f.force[i] * x[node_dof(f.node, i)];
  return s;
}

double DeadLoad::work(double t, std::span<const double> x) const {
  // W_n+1 = W_n + ½ (λ_n + λ_n+1) (S_n+1 − S_n)   (L13)
  const double mean_factor = 0.5 * (ramp_.factor(t_accepted_) + ramp_.factor(t));
  return work_ + mean_factor * (projected_displacement(x) - s_accepted_);
}

void DeadLoad::accept_step(std::span<const double> x) {
  work_ = work(t_current_, x);
  s_accepted_ = projected_displacement(x);
  t_accepted_ = t_current_;
}

std::vector<double> DeadLoad::save_state() const { return {t_accepted_, s_accepted_, work_}; }

void DeadLoad::load_state(std::span<const double> state) {
  PLISSE_CHECK(state.size() == 3, "load '" << name_ << "': checkpoint state has " << state.size()
                                           << " values, expected 3 (t, S, W)");
  for (double v : state)
    PLISSE_CHECK(std::isfinite(v), "load '" << name_ << "': checkpoint state is not finite");
  t_accepted_ = t_current_ = state[0];
  s_accepted_ = state[1];
  work_ = state[2];
}

std::vector<std::string> DeadLoad::history_columns() const {
  return {"load_x:" + name_, "load_y:" + name_, "load_z:" + name_, "work:" + name_};
}

std::vector<double> DeadLoad::history_values(double t, std::span<const double> x) const {
  const Vec3d load = ramp_.factor(t) * total_;
  return {load.x(), load.y(), load.z(), work(t, x)};
}

}  // namespace plisse
