#include "physics/die_contact.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "physics/cavity_volume.hpp"
#include "physics/die_surface.hpp"
#include "physics/dirichlet.hpp"
#include "physics/surface.hpp"

namespace plisse {

DieContact::DieContact(const Mesh& mesh, DieGeometry die, DieContactSettings settings,
                       const std::vector<std::array<int, 3>>& candidates,
                       const std::vector<std::array<int, 3>>& region, int mirror_planes)
    : mesh_(mesh),
      die_(std::move(die)),
      settings_(std::move(settings)),
      cut_planes_(die_.symmetric_planes(mirror_planes)) {
  PLISSE_CHECK(settings_.penalty > 0.0, "die '" << settings_.name << "': penalty must be > 0 (got "
                                                << settings_.penalty << ")");
  PLISSE_CHECK(settings_.tolerance > 0.0, "die '" << settings_.name
                                                  << "': tolerance must be > 0 (got "
                                                  << settings_.tolerance << ")");
  PLISSE_CHECK(region.empty() || settings_.contact == ContactKind::sticking,
               "die '" << settings_.name << "': only a sticking die glues a region");
  PLISSE_CHECK(settings_.friction >= 0.0, "die '" << settings_.name
                                                  << "': friction must be >= 0 (got "
                                                  << settings_.friction << ")");
  PLISSE_CHECK(settings_.friction == 0.0 || settings_.contact == ContactKind::coulomb,
               "die '" << settings_.name << "': only a Coulomb die has a friction coefficient");
  // Each triangle once, whichever list it comes from, so a region inside the candidate surface
  // does not double the area.
  std::set<std::array<int, 3>> seen;
  std::vector<std::array<int, 3>> all;
  for (const auto* list : {&candidates, &region})
    for (auto t : *list) {
      std::sort(t.begin(), t.end());
      if (seen.insert(t).second) all.push_back(t);
    }
  const std::vector<SurfaceFace> faces = faces_with_corners(mesh_, all);
  const std::map<int, double> contact = tributary_areas(mesh_, faces);
  const bool sticking = settings_.contact == ContactKind::sticking;
  // A sticking die also ties the corners of second-order faces, which carry no contact weight
  // (D16) but a positive tie weight (D17); a frictionless die leaves them out.
  for (const auto& [node, tie] : tie_areas(mesh_, faces)) {
    const auto it = contact.find(node);
    const double area = it == contact.end() ? 0.0 : it->second;
    if (area == 0.0 && !sticking) continue;
    nodes_.push_back(node);
    areas_.push_back(area);
    tie_areas_.push_back(sticking ? tie : area);
  }
  state_.resize(nodes_.size());
  // Coulomb nodes stick, when they touch, from where they are at t = 0 (D18).
  if (settings_.contact == ContactKind::coulomb)
    for (size_t i = 0; i < nodes_.size(); ++i)
      state_[i].anchor = mesh_.nodes[nodes_[i]] - die_.point(0.0);
  // Region nodes, and the nodes of a sticking die that lie on it at t = 0, are glued where they
  // are: at their reference positions (D13).
  const std::set<int> region_nodes = surface_nodes(faces_with_corners(mesh_, region));
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const Vec3d& X = mesh_.nodes[nodes_[i]];
    if (region_nodes.count(nodes_[i]) ||
        (sticking && std::abs(die_.gap(X, 0.0).g) <= settings_.touch_slack)) {
      state_[i].glued = true;
      state_[i].anchor = X - die_.point(0.0);
    }
  }
  accepted_ = state_;
}

Vec3d DieContact::position(int i, std::span<const double> x) const {
  return deformed_position(mesh_, x, nodes_[i]);
}

DieContact::NodeResponse DieContact::respond(int i, double t, std::span<const double> x,
                                             bool with_tangent) const {
  NodeResponse out;
  const NodeState& s = state_[i];
  const double A = areas_[i], eps = settings_.penalty;
  const Vec3d xi = position(i, x);
  if (s.glued) {
    // Tie to the die point: d = x - (c(t) + s), f = W (Lambda - eps d), K = W eps I   (D12, D17)
    const double W = tie_areas_[i];
    const Vec3d d = xi - (die_.point(t) + s.anchor);
    out.force = W * (s.vector_multiplier - eps * d);
    if (with_tangent) out.K = W * eps * Mat3d::Identity();
    out.contact = Contact::sticking;
    out.violation = d.norm();
    return out;
  }
  if (A == 0.0) return out;  // a corner of a second-order face: tied once glued, else free (D16)
  const DieGap gap = die_.gap(xi, t);
  out.violation = std::max(0.0, -gap.g);
  // lambda_hat = max(0, lambda - eps g), f = A lambda_hat n   (D6)
  const double lambda_hat = s.multiplier - eps * gap.g;
  if (lambda_hat <= 0.0) return out;
  out.contact = Contact::sliding;
  out.force = A * lambda_hat * gap.n;
  // K = -df/dx = A (eps n n^T - lambda_hat H)   (D8)
  if (with_tangent) out.K = A * (eps * gap.n * gap.n.transpose() - lambda_hat * gap.H);
  if (settings_.contact == ContactKind::coulomb)
    add_friction(i, t, xi, gap, lambda_hat, with_tangent, out);
  return out;
}

void DieContact::add_friction(int i, double t, const Vec3d& xi, const DieGap& gap,
                              double lambda_hat, bool with_tangent, NodeResponse& out) const {
  const NodeState& s = state_[i];
  const double A = areas_[i], eps = settings_.penalty, mu = settings_.friction;
  const Vec3d& n = gap.n;
  const Mat3d P = Mat3d::Identity() - n * n.transpose();
  // Slip in the step r, its tangential part d and the trial traction tau* = P Lambda - eps d
  // (D18).
  const Vec3d r = xi - die_.point(t) - s.anchor;
  const Vec3d d = P * r;
  const Vec3d trial = P * s.vector_multiplier - eps * d;
  const double bound = mu * lambda_hat, size = trial.norm();
  const bool sticks = bound > 0.0 && size <= bound;
  // tau = tau* inside the cone, bound tau*/|tau*| on it   (D19)
  out.traction = sticks || size == 0.0 ? trial : Vec3d((bound / size) * trial);
  out.force += A * out.traction;
  out.contact = sticks ? Contact::sticking : Contact::sliding;
  if (sticks) out.violation = std::max(out.violation, d.norm());
  // Sliding with a zero trial traction (friction 0 at a node that has not slipped): tau = 0.
  if (!with_tangent || (!sticks && size == 0.0)) return;
  // d tau*/dx, with dP/dx acting on a vector v: -(n . v) H - n (H v)^T   (D20)
  const Vec3d& Lambda = s.vector_multiplier;
  const Mat3d dtrial = -n.dot(Lambda) * gap.H - n * (gap.H * Lambda).transpose() -
                       eps * (P - n.dot(r) * gap.H - n * (gap.H * r).transpose());
  if (sticks) {
    out.K -= A * dtrial;
    return;
  }
  // On the cone: d tau/dx = t (mu d lambda_hat/dx) + (bound/|tau*|) (I - t t^T) d tau*/dx, with
  // d lambda_hat/dx = -eps n^T   (D20)
  const Vec3d unit = trial / size;
  out.K -= A * (-mu * eps * unit * n.transpose() +
                (bound / size) * (Mat3d::Identity() - unit * unit.transpose()) * dtrial);
}

void DieContact::assemble(double t, std::span<const double> x, std::span<double> residual,
                          TangentSink* tangent) {
  time_ = t;
  std::array<int, 3> dofs;
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> k;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const NodeResponse r = respond(static_cast<int>(i), t, x, tangent != nullptr);
    if (r.contact == Contact::none) continue;
    for (int c = 0; c < 3; ++c) {
      dofs[c] = node_dof(nodes_[i], c);
      residual[dofs[c]] -= r.force[c];  // residual = internal - external force (D7)
    }
    if (!tangent) continue;
    k = r.K;
    tangent->add(dofs, dofs, std::span<const double>(k.data(), 9));
  }
}

DieContact::Contact DieContact::reported(int i, Contact in_step) const {
  // After accept_step a Coulomb node that slid sits on its cone's surface with no slip since:
  // what it did in that step is its state.
  if (in_step == Contact::none || settings_.contact != ContactKind::coulomb) return in_step;
  return state_[i].slid ? Contact::sliding : Contact::sticking;
}

std::pair<int, int> DieContact::count_sticking_and_sliding(double t, std::span<const double> x,
                                                           bool as_reported) const {
  std::pair<int, int> out{0, 0};
  for (size_t i = 0; i < nodes_.size(); ++i) {
    Contact c = respond(static_cast<int>(i), t, x, false).contact;
    if (as_reported) c = reported(static_cast<int>(i), c);
    out.first += c == Contact::sticking;
    out.second += c == Contact::sliding;
  }
  return out;
}

bool DieContact::symmetric() const {
  return settings_.contact != ContactKind::coulomb || settings_.friction == 0.0;
}

bool DieContact::update_multipliers(std::span<const double> x) {
  if (violation(time_, x) <= settings_.tolerance) return false;
  const double eps = settings_.penalty;
  const bool coulomb = settings_.contact == ContactKind::coulomb;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    NodeState& s = state_[i];
    const Vec3d xi = position(static_cast<int>(i), x);
    if (s.glued) {
      // Lambda <- Lambda - eps d   (D14)
      s.vector_multiplier -= eps * (xi - (die_.point(time_) + s.anchor));
    } else if (areas_[i] > 0.0) {
      // Lambda <- tau, from the multipliers before this update   (D21)
      if (coulomb) s.vector_multiplier = respond(static_cast<int>(i), time_, x, false).traction;
      // lambda <- max(0, lambda - eps g)   (D9)
      s.multiplier = std::max(0.0, s.multiplier - eps * die_.gap(xi, time_).g);
    }
  }
  return true;
}

void DieContact::accept_step(std::span<const double> x) {
  if (settings_.contact == ContactKind::sticking) {
    const double eps = settings_.penalty;
    for (size_t i = 0; i < nodes_.size(); ++i) {
      NodeState& s = state_[i];
      if (s.glued) continue;
      const Vec3d xi = position(static_cast<int>(i), x);
      const DieGap gap = die_.gap(xi, time_);
      const double lambda_hat = areas_[i] > 0.0 ? std::max(0.0, s.multiplier - eps * gap.g) : 0.0;
      if (gap.g > settings_.touch_slack && lambda_hat <= 0.0) continue;
      s.glued = true;
      if (areas_[i] == 0.0) {
        // A corner of a second-order face, which may lie inside the die by the sagitta of its
        // faces (D16): glued where it is, without force (D17).
        s.anchor = xi - die_.point(time_);
        s.vector_multiplier = Vec3d::Zero();
        continue;
      }
      // Glue to the closest die point x - g n, with Lambda = ((A / W) lambda_hat + eps g) n so
      // the force of the node does not jump (D13, D17).
      s.anchor = xi - gap.g * gap.n - die_.point(time_);
      s.vector_multiplier = (areas_[i] / tie_areas_[i] * lambda_hat + eps * gap.g) * gap.n;
    }
  } else if (settings_.contact == ContactKind::coulomb) {
    // The next step starts from the traction reached and sticks from here   (D22)
    std::vector<NodeResponse> responses(nodes_.size());
    for (size_t i = 0; i < nodes_.size(); ++i)
      responses[i] = respond(static_cast<int>(i), time_, x, false);
    for (size_t i = 0; i < nodes_.size(); ++i) {
      state_[i].vector_multiplier = responses[i].traction;
      state_[i].anchor = position(static_cast<int>(i), x) - die_.point(time_);
      state_[i].slid = responses[i].contact == Contact::sliding;
    }
  }
  accepted_ = state_;
}

void DieContact::reject_step() { state_ = accepted_; }

std::vector<double> DieContact::save_state() const {
  std::vector<double> out;
  out.reserve(8 * accepted_.size());
  for (const NodeState& s : accepted_) {
    out.push_back(s.glued ? 1.0 : s.slid ? 2.0 : 0.0);
    out.push_back(s.multiplier);
    out.insert(out.end(), s.vector_multiplier.data(), s.vector_multiplier.data() + 3);
    out.insert(out.end(), s.anchor.data(), s.anchor.data() + 3);
  }
  return out;
}

void DieContact::load_state(std::span<const double> state) {
  PLISSE_CHECK(state.size() == 8 * accepted_.size(),
               "die '" << settings_.name << "': the checkpoint has " << state.size() / 8
                       << " contact nodes, the model " << accepted_.size());
  for (size_t i = 0; i < accepted_.size(); ++i) {
    const double* v = state.data() + 8 * i;
    NodeState& s = accepted_[i];
    s.glued = v[0] == 1.0;
    s.slid = v[0] == 2.0;
    s.multiplier = v[1];
    s.vector_multiplier = Vec3d(v[2], v[3], v[4]);
    s.anchor = Vec3d(v[5], v[6], v[7]);
  }
  state_ = accepted_;
}

std::vector<std::string> DieContact::history_columns() const {
  const std::string& n = settings_.name;
  std::vector<std::string> columns = {"force_x:" + n, "force_y:" + n, "force_z:" + n,
                                      "contact_nodes:" + n, "penetration:" + n};
  if (settings_.contact == ContactKind::coulomb) {
    columns.push_back("stick_nodes:" + n);
    columns.push_back("slip_nodes:" + n);
  }
  if (cut_planes_ != 0)
    columns.insert(columns.end(), {"full_force_x:" + n, "full_force_y:" + n, "full_force_z:" + n});
  return columns;
}

std::vector<double> DieContact::history_values(double t, std::span<const double> x) const {
  const Vec3d f = force_on_die(t, x);
  std::vector<double> values = {f[0], f[1], f[2], static_cast<double>(n_contact_nodes(t, x)),
                                violation(t, x)};
  if (settings_.contact == ContactKind::coulomb) {
    const auto [stick, slip] = count_sticking_and_sliding(t, x, true);
    values.push_back(stick);
    values.push_back(slip);
  }
  if (cut_planes_ != 0) {
    const Vec3d whole = whole_body_force(f, cut_planes_);
    values.insert(values.end(), {whole[0], whole[1], whole[2]});
  }
  return values;
}

std::vector<NodeField> DieContact::node_fields(double t, std::span<const double> x,
                                               int n_nodes) const {
  const std::string& name = settings_.name;
  NodeField state{"contact_" + name, std::vector<double>(n_nodes, 0.0)};
  NodeField pressure{"contact_pressure_" + name, std::vector<double>(n_nodes, 0.0)};
  NodeField gap{"gap_" + name, std::vector<double>(n_nodes, 0.0)};
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const int v = nodes_[i];
    const NodeResponse r = respond(static_cast<int>(i), t, x, false);
    state.values[v] = static_cast<double>(reported(static_cast<int>(i), r.contact));
    const DieGap g = die_.gap(position(static_cast<int>(i), x), t);
    gap.values[v] = g.g;
    // The normal part of the die's force per reference area (D15): the contact pressure.
    const double weight = state_[i].glued ? tie_areas_[i] : areas_[i];
    if (weight > 0.0) pressure.values[v] = r.force.dot(g.n) / weight;
  }
  return {state, pressure, gap};
}

Vec3d DieContact::force_on_die(double t, std::span<const double> x) const {
  // F_die = - sum_v f_v   (D15)
  Vec3d sum = Vec3d::Zero();
  for (size_t i = 0; i < nodes_.size(); ++i) sum -= respond(static_cast<int>(i), t, x, false).force;
  return sum;
}

double DieContact::violation(double t, std::span<const double> x) const {
  double worst = 0.0;
  for (size_t i = 0; i < nodes_.size(); ++i)
    worst = std::max(worst, respond(static_cast<int>(i), t, x, false).violation);
  return worst;
}

int DieContact::n_contact_nodes(double t, std::span<const double> x) const {
  int n = 0;
  for (size_t i = 0; i < nodes_.size(); ++i)
    n += respond(static_cast<int>(i), t, x, false).contact != Contact::none;
  return n;
}

int DieContact::n_glued() const {
  return static_cast<int>(
      std::count_if(state_.begin(), state_.end(), [](const NodeState& s) { return s.glued; }));
}

std::pair<int, int> DieContact::sticking_and_sliding(double t, std::span<const double> x) const {
  return count_sticking_and_sliding(t, x, false);
}

std::vector<RigidHold> DieContact::rigid_holds(double t) const {
  std::vector<RigidHold> holds;
  const bool sticks = settings_.contact == ContactKind::coulomb && settings_.friction > 0.0;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const int node = nodes_[i];
    const Vec3d& X = mesh_.nodes[static_cast<size_t>(node)];
    bool all_ways = state_[i].glued;
    if (!all_ways) {
      if (areas_[i] == 0.0) continue;  // a second-order face's corner: glue only (D16)
      DieGap gap;
      bool deep = false;
      try {
        gap = die_.gap(X, t);
      } catch (const Error&) {  // on a sphere's centre or a cylinder's axis: deep inside
        deep = true;
      }
      // A node that only touches carries no force yet (D6), but the first iterate pushes it in
      // wherever a load presses the body onto the die, and the contact holds from there on: it
      // counts (a sheet pressed onto a plate it rests on solves in two steps).
      if (!deep && gap.g > settings_.touch_slack) continue;
      all_ways = sticks || deep;
      if (!all_ways) holds.push_back({{node}, X, gap.n, false});
    }
    if (all_ways)
      for (int k = 0; k < 3; ++k) holds.push_back({{node}, X, Vec3d::Unit(k), false});
  }
  return holds;
}

std::optional<size_t> DieContact::index_of(int node) const {
  const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), node);
  if (it == nodes_.end() || *it != node) return std::nullopt;
  return static_cast<size_t>(it - nodes_.begin());
}

bool DieContact::glued(int node) const {
  const auto i = index_of(node);
  return i && state_[*i].glued;
}

double DieContact::area(int node) const {
  const auto i = index_of(node);
  return i ? areas_[*i] : 0.0;
}

double DieContact::tie_area(int node) const {
  const auto i = index_of(node);
  return i ? tie_areas_[*i] : 0.0;
}

double default_die_penalty(double shear_modulus, double element_size) {
  // epsilon = 10 mu / h   (D11)
  return 10.0 * shear_modulus / element_size;
}

}  // namespace plisse
