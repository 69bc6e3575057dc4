#include "physics/cavity.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "physics/cavity_volume.hpp"
#include "physics/follower_pressure.hpp"
#include "physics/pressure_load.hpp"
#include "physics/surface.hpp"

namespace plisse {
namespace {

std::string describe_node(const Mesh& mesh, int node) {
  std::ostringstream out;
  const Vec3d& X = mesh.nodes[node];
  out << node << " (" << X[0] << ", " << X[1] << ", " << X[2] << ")";
  return out.str();
}

}  // namespace

CavityTerm::CavityTerm(const Cavity& cavity, const Mesh& mesh,
                       const std::vector<ConstrainedComponent>& constraints, int mirror_planes,
                       const std::vector<CapNodes>& caps, double imperfection)
    : mesh_(mesh), cavity_(cavity), faces_(outward_faces(mesh, cavity.surface.name)) {
  const InputPlace& place = cavity.surface.place;
  WallClosure closure = close_over_caps(mesh, faces_, caps);
  if (const auto edge = closure.open_edge) {
    int count = 0;
    for (const auto& f : faces_)
      for (int k = 0; k < 3; ++k)
        count += (f.nodes[k] == (*edge)[0] && f.nodes[(k + 1) % 3] == (*edge)[1]) ||
                 (f.nodes[k] == (*edge)[1] && f.nodes[(k + 1) % 3] == (*edge)[0]);
    std::ostringstream rule;
    rule << "surface '" << cavity.surface.name << "' of cavity '" << cavity.name
         << "' is not closed: the edge between nodes " << describe_node(mesh, (*edge)[0]) << " and "
         << describe_node(mesh, (*edge)[1]) << " belongs to " << count
         << " triangle(s) of it, does not lie on a symmetry plane x = 0, y = 0 or z = 0 and is "
            "not tied by a cap (or ends a cap's rim off those planes); a cavity's wall must be "
            "closed, by itself, by those planes or by the caps on its rims "
            "(docs/theory/cavities.md, C2 and C14)";
    throw InputError(place, rule.str());
  }
  closures_ = std::move(closure.caps);
  full_body_factor_ = full_body_factor(closure.planes & mirror_planes);
  reference_volume_ = volume(std::vector<double>(kValuesPerNode * mesh.n_nodes(), 0.0));
  // A wall that lies in the planes that close it (a flat sheet's face on z = 0) encloses nothing:
  // V0 is then round-off of the wall's size, taken as 0 (C8).
  double area = 0.0;
  for (const SurfaceFace& f : faces_) {
    const Vec3d& X0 = mesh.nodes[f.nodes[0]];
    area += 0.5 * (mesh.nodes[f.nodes[1]] - X0).cross(mesh.nodes[f.nodes[2]] - X0).norm();
  }
  const double round_off = kFlatVolumeTolerance * area * std::sqrt(area);
  if (std::abs(reference_volume_) <= round_off) reference_volume_ = 0.0;
  // An imperfection of a flat wall moves each node at most `imperfection` along any direction,
  // so the volume it encloses by at most imperfection × A, of either sign: such a wall starts
  // flat too, and keeps the V0 it has, which the volume's ramp starts from (C8).
  const bool flat = std::abs(reference_volume_) <= round_off + imperfection * area;
  if (reference_volume_ < 0.0 && !flat) {
    std::ostringstream rule;
    rule << "surface '" << cavity.surface.name << "' of cavity '" << cavity.name
         << "' encloses the volume " << reference_volume_
         << " mm^3, which is negative: a cavity lies on the side of its wall away from the "
            "body (e.g. a balloon's 'inner' surface, not 'outer')";
    if (imperfection > 0.0)
      rule << "; more than the imperfection of " << imperfection << " mm can take from a flat "
           << "wall of " << area << " mm^2";
    throw InputError(place, rule.str());
  }
  const std::string starts_flat =
      "cavity '" + cavity.name + "' starts flat (its wall '" + cavity.surface.name +
      (reference_volume_ == 0.0 ? "' encloses no volume)"
                                : "' encloses no volume but what its imperfection makes)");
  if (flat && cavity.control == CavityControl::gas && cavity.reservoir_volume == 0.0)
    throw InputError(place, starts_flat +
                                ", so an ideal gas in it has no initial amount: use `control: "
                                "volume` with `volume` or `volume_change`, or give the gas a "
                                "`reservoir_volume` to start in");
  if (flat && cavity.control == CavityControl::volume && cavity.target == VolumeTarget::ratio)
    throw InputError(cavity.target_place.line > 0 ? cavity.target_place : place,
                     starts_flat +
                         ", so a volume ratio has nothing to multiply: give `volume` (mm^3) or "
                         "`volume_change` (mm^3) instead");
  if (cavity.control == CavityControl::volume && !(final_volume() > 0.0)) {
    std::ostringstream rule;
    rule << "cavity '" << cavity.name << "': the volume at the end of the ramp, V0 + "
         << "volume_change = " << reference_volume_ << " + " << cavity.volume_change << " = "
         << final_volume() << " mm^3, is not positive";
    throw InputError(cavity.target_place.line > 0 ? cavity.target_place : place, rule.str());
  }
  const std::set<int> nodes = surface_nodes(faces_);
  nodes_.assign(nodes.begin(), nodes.end());
  symmetric_ = pressure_stiffness_is_symmetric(mesh, faces_, constraints, closures_);
}

void CavityTerm::add_couplings(std::vector<std::pair<int, int>>& pairs) const {
  for (int v : nodes_)
    for (int i = 0; i < 3; ++i) {
      pairs.emplace_back(pressure_dof_, node_dof(v, i));
      pairs.emplace_back(node_dof(v, i), pressure_dof_);
    }
  pairs.emplace_back(pressure_dof_, pressure_dof_);
  for (const CapClosure& closure : closures_)
    add_cap_closure_couplings(closure, pressure_dof_, pairs);
}

double CavityTerm::volume(std::span<const double> x) const {
  return closed_volume(mesh_, faces_, closures_, x);
}

double CavityTerm::fluid_volume(double p_c, double t) const {
  const double ramp = cavity_.ramp.factor(t);
  if (cavity_.control == CavityControl::volume) {  // (cavities.md, C8)
    // The ratio form as written before `volume` and `volume_change` existed: the same bits.
    if (cavity_.target == VolumeTarget::ratio)
      return reference_volume_ * (1.0 + (cavity_.volume_ratio - 1.0) * ramp);
    return reference_volume_ + (final_volume() - reference_volume_) * ramp;
  }
  // (C9): V_c = (V0 + V_r) m(t) ((p0 + p_amb) / (p_c + p_amb))^(1/gamma) - V_r
  const double p_amb = cavity_.ambient_pressure;
  PLISSE_CHECK(p_c + p_amb > 0.0, "cavity '" << cavity_.name
                                             << "': the absolute gas pressure p_c + p_amb = "
                                             << p_c + p_amb << " MPa is not positive");
  const double mass = 1.0 + (cavity_.mass_ratio - 1.0) * ramp;
  // The isothermal gas without a reservoir, as written before either existed: the same bits.
  if (cavity_.gamma == 1.0 && cavity_.reservoir_volume == 0.0)
    return (cavity_.initial_pressure + p_amb) * reference_volume_ * mass / (p_c + p_amb);
  const double reservoir = modelled_reservoir();
  const double ratio = (cavity_.initial_pressure + p_amb) / (p_c + p_amb);
  // No power for the isothermal gas (gamma = 1): its volume is exactly inverse to the pressure.
  const double expansion = cavity_.gamma == 1.0 ? ratio : std::pow(ratio, 1.0 / cavity_.gamma);
  return (reference_volume_ + reservoir) * mass * expansion - reservoir;
}

double CavityTerm::modelled_reservoir() const {
  return cavity_.reservoir_volume / full_body_factor_;
}

double CavityTerm::final_volume() const {
  switch (cavity_.target) {
    case VolumeTarget::ratio:
      return reference_volume_ * cavity_.volume_ratio;
    case VolumeTarget::absolute:
      return cavity_.volume;
    case VolumeTarget::change:
      return reference_volume_ + cavity_.volume_change;
  }
  return reference_volume_;
}

double CavityTerm::fluid_volume_derivative(double p_c, double t) const {
  if (cavity_.control == CavityControl::volume) return 0.0;
  // (C11): d V_c / d p_c = -V_gas / (gamma (p_c + p_amb)), V_gas = V_c + V_r
  return -(fluid_volume(p_c, t) + modelled_reservoir()) /
         (cavity_.gamma * (p_c + cavity_.ambient_pressure));
}

template <int N>
void CavityTerm::add_face(const SurfaceFace& face, double p, std::span<const double> x,
                          std::span<double> residual, TangentSink* tangent,
                          double& six_volume) const {
  // One bordered block per face: its 3 N displacement dofs and p_c.
  constexpr int n = 3 * N;
  std::array<int, n + 1> dofs;
  dofs[n] = pressure_dof_;
  std::array<Vec3d, N> xs;
  for (int a = 0; a < N; ++a) {
    xs[a] = deformed_position(mesh_, x, face.nodes[a]);
    for (int i = 0; i < 3; ++i) dofs[3 * a + i] = node_dof(face.nodes[a], i);
  }
  Eigen::Matrix<double, n + 1, n + 1, Eigen::RowMajor> k;
  if constexpr (N == 3) {
    six_volume -= xs[0].dot(xs[1].cross(xs[2]));                            // (C1)
    const Vec3d c = add_follower_pressure_residual(p, xs, dofs, residual);  // (C6)
    if (!tangent) return;
    k.setZero();
    follower_pressure_stiffness(p, xs, k.template topLeftCorner<n, n>());  // (C10)
    // (C11): column d r_u / d p_c = c/6; row d r_p / d x_a = (1/6) x_{a+1} x x_{a+2}
    for (int a = 0; a < 3; ++a) {
      k.template block<3, 1>(3 * a, n) = c / 6.0;
      k.template block<1, 3>(n, 3 * a) = xs[(a + 1) % 3].cross(xs[(a + 2) % 3]).transpose() / 6.0;
    }
  } else {
    six_volume -= 6.0 * quadratic_cone_volume(xs);                                         // (C12)
    const std::array<Vec3d, N> g = add_follower_pressure_residual(p, xs, dofs, residual);  // (C6)
    if (!tangent) return;
    k.setZero();
    follower_pressure_stiffness(p, xs, k.template topLeftCorner<n, n>());  // (C10)
    // (C11, C13): column d r_u / d p_c = g_a; row d r_p / d x_a = gradient of the cone volume
    const std::array<Vec3d, N> row = quadratic_cone_volume_gradient(xs);
    for (int a = 0; a < N; ++a) {
      k.template block<3, 1>(3 * a, n) = g[a];
      k.template block<1, 3>(n, 3 * a) = row[a].transpose();
    }
  }
  tangent->add(dofs, dofs, std::span<const double>(k.data(), (n + 1) * (n + 1)));
}

void CavityTerm::assemble(double t, std::span<const double> x, std::span<double> residual,
                          TangentSink* tangent) {
  PLISSE_ASSERT(pressure_dof_ >= 0);
  const double p = x[pressure_dof_];
  const double fluid = fluid_volume(p, t);
  double six_volume = 0.0;
  for (const SurfaceFace& face : faces_) {
    if (face.n_nodes == 3)
      add_face<3>(face, p, x, residual, tangent, six_volume);
    else
      add_face<6>(face, p, x, residual, tangent, six_volume);
  }
  for (const CapClosure& closure : closures_)  // (C16-C17)
    add_cap_closure(mesh_, closure, p, x, residual, tangent, pressure_dof_, six_volume);
  residual[pressure_dof_] += -(six_volume / 6.0 - fluid);  // (C7)
  if (tangent) {
    const double d = fluid_volume_derivative(p, t);  // always inserted: a diagonal entry exists
    tangent->add(std::span<const int>(&pressure_dof_, 1), std::span<const int>(&pressure_dof_, 1),
                 std::span<const double>(&d, 1));
  }
}

int CavityTerm::negative_directions() const {
  // (stability.md, S6): with the pivot d of the (p_c, p_c) entry taken first, the bordered matrix
  // is congruent to diag(d, K - g d^-1 g^T); d < 0 (gas, C11) gives one negative pivot and leaves
  // K + g g^T / |d|, the tangent with the gas stiffness. With d = 0 (volume control, C8) the pair
  // (g, p_c) is congruent to diag(+1, -1) on span(g) and K restricted to g^T du = 0: again one.
  // A polytropic gas always has d = -V_gas/(gamma (p_c + p_amb)) < 0 (fluid_volume refuses a
  // non-positive p_c + p_amb), so both controls give 1; a control with d > 0 would need the sign
  // of d - g^T K^-1 g instead.
  return 1;
}

std::vector<std::string> CavityTerm::history_columns() const {
  std::vector<std::string> columns = {"pressure:" + cavity_.name, "volume:" + cavity_.name};
  if (full_body_factor_ > 1) columns.push_back("full_volume:" + cavity_.name);
  return columns;
}

std::vector<double> CavityTerm::history_values(double, std::span<const double> x) const {
  const double v = volume(x);
  std::vector<double> values = {x[pressure_dof_], v};
  if (full_body_factor_ > 1) values.push_back(full_body_factor_ * v);
  return values;
}

}  // namespace plisse
