#include "physics/surface_contact.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <unsupported/Eigen/BVH>

#include "core/error.hpp"
#include "physics/cavity_volume.hpp"
#include "physics/die_surface.hpp"
#include "physics/node_facet_gap.hpp"
#include "physics/surface.hpp"

namespace plisse {
namespace {

using Box = Eigen::AlignedBox3d;
using Tree = Eigen::KdBVH<double, 3, int>;

/// The flat facets of `faces`: a linear face itself, a 6-node face its four sub-triangles, each
/// with the face's orientation (N1).
std::vector<std::array<int, 3>> flat_facets(const std::vector<SurfaceFace>& faces) {
  std::vector<std::array<int, 3>> out;
  for (const SurfaceFace& f : faces) {
    const auto& n = f.nodes;
    if (f.n_nodes == 3) {
      out.push_back({n[0], n[1], n[2]});
      continue;
    }
    // Corners 0, 1, 2; edge nodes 3 (01), 4 (12), 5 (20).
    out.push_back({n[0], n[3], n[5]});
    out.push_back({n[3], n[1], n[4]});
    out.push_back({n[5], n[4], n[2]});
    out.push_back({n[3], n[4], n[5]});
  }
  return out;
}

/// The facets' bounding boxes at `points`, grown by `margin`, in Eigen's KdBVH: which facets may
/// lie within `margin` of a point (N4).
class FacetSearch {
 public:
  FacetSearch(const std::vector<std::array<int, 3>>& facets, const std::vector<Vec3d>& points,
              double margin)
      : boxes_(facets.size()) {
    std::vector<int> ids(facets.size());
    for (size_t f = 0; f < facets.size(); ++f) {
      for (int v : facets[f]) boxes_[f].extend(points[v]);
      boxes_[f] =
          Box(boxes_[f].min() - Vec3d::Constant(margin), boxes_[f].max() + Vec3d::Constant(margin));
      ids[f] = static_cast<int>(f);
    }
    tree_.init(ids.begin(), ids.end(), boxes_.begin(), boxes_.end());
  }
  /// The facets whose grown boxes contain p, increasing.
  std::vector<int> containing(const Vec3d& p) const {
    Query query{boxes_, p, {}};
    Eigen::BVIntersect(tree_, query);
    std::sort(query.found.begin(), query.found.end());
    return query.found;
  }

 private:
  struct Query {
    const std::vector<Box>& boxes;
    Vec3d point;
    std::vector<int> found;
    bool intersectVolume(const Box& box) const { return box.contains(point); }
    bool intersectObject(int facet) {
      if (boxes[facet].contains(point)) found.push_back(facet);
      return false;  // never stop early
    }
  };
  std::vector<Box> boxes_;
  Tree tree_;
};

/// Unit normal of the flat facet f at the positions `points`.
Vec3d facet_normal(const std::array<int, 3>& f, const std::vector<Vec3d>& points) {
  return (points[f[1]] - points[f[0]]).cross(points[f[2]] - points[f[0]]).normalized();
}

/// Barycentric coordinates >= -kInside count as on the facet: a node just beyond a free edge of
/// the interface keeps its facet when the two surfaces stretch by slightly different amounts
/// (N4).
constexpr double kInside = 0.1;

}  // namespace

SurfaceContact::SurfaceContact(const Mesh& mesh, SurfaceContactSettings settings,
                               const std::vector<std::array<int, 3>>& nodes_from,
                               const std::vector<std::array<int, 3>>& facets_from, bool self)
    : mesh_(mesh), settings_(std::move(settings)), self_(self) {
  const std::string& name = settings_.name;
  PLISSE_CHECK(settings_.penalty > 0.0,
               "contact '" << name << "': penalty must be > 0 (got " << settings_.penalty << ")");
  PLISSE_CHECK(settings_.tolerance > 0.0, "contact '" << name << "': tolerance must be > 0 (got "
                                                      << settings_.tolerance << ")");
  PLISSE_CHECK(settings_.search_distance > 0.0,
               "contact '" << name << "': search distance must be > 0 (got "
                           << settings_.search_distance << ")");
  PLISSE_CHECK(!nodes_from.empty() && !facets_from.empty(),
               "contact '" << name << "': empty surface");
  const std::vector<SurfaceFace> node_faces = faces_with_corners(mesh_, nodes_from);
  facets_ = flat_facets(faces_with_corners(mesh_, facets_from));
  const std::vector<std::array<int, 3>> own = flat_facets(node_faces);
  // Contact nodes: those with a contact weight (D5, D16; not the corners of 6-node faces).
  for (const auto& [node, area] : tributary_areas(mesh_, node_faces)) {
    if (area == 0.0) continue;
    nodes_.push_back(node);
    areas_.push_back(area);
  }
  std::map<int, size_t> index;
  for (size_t i = 0; i < nodes_.size(); ++i) index[nodes_[i]] = i;
  node_faces_.resize(nodes_.size());
  own_facets_ = own;
  for (size_t f = 0; f < own.size(); ++f)
    for (int v : own[f])
      if (const auto it = index.find(v); it != index.end()) node_faces_[it->second].push_back(f);
  // On a shell the faces lie half the reference thickness off the mid-surface that carries the
  // nodes: a node's own half thickness (the mean of its faces') and the facet's (N14).
  node_offsets_.assign(nodes_.size(), 0.0);
  facet_offsets_.assign(facets_.size(), 0.0);
  if (mesh_.is_shell()) {
    const std::vector<double> own_thickness = shell_thickness(mesh_, nodes_from);
    for (size_t i = 0; i < nodes_.size(); ++i) {
      for (int f : node_faces_[i]) node_offsets_[i] += own_thickness[f];
      node_offsets_[i] *= 0.5 / static_cast<double>(node_faces_[i].size());
    }
    const std::vector<double> facet_thickness = shell_thickness(mesh_, facets_from);
    for (size_t f = 0; f < facets_.size(); ++f) facet_offsets_[f] = 0.5 * facet_thickness[f];
    widest_offset_ = *std::max_element(node_offsets_.begin(), node_offsets_.end()) +
                     *std::max_element(facet_offsets_.begin(), facet_offsets_.end());
  }
  // Facets a node skips: those that contain it and, in self contact or on a shell (whose two
  // faces hold the same triangles), those that touch one of its own facets (N4).
  std::map<int, std::vector<int>> facets_at;
  for (size_t f = 0; f < facets_.size(); ++f)
    for (int v : facets_[f]) facets_at[v].push_back(static_cast<int>(f));
  excluded_.resize(nodes_.size());
  for (size_t i = 0; i < nodes_.size(); ++i) {
    std::set<int> near = {nodes_[i]};
    if (self_ || mesh_.is_shell())
      for (int f : node_faces_[i])
        for (int v : own[f]) near.insert(v);
    std::set<int> skip;
    for (int v : near)
      if (const auto it = facets_at.find(v); it != facets_at.end())
        skip.insert(it->second.begin(), it->second.end());
    excluded_[i].assign(skip.begin(), skip.end());
  }
  multipliers_.assign(nodes_.size(), 0.0);
  accepted_ = multipliers_;
  const std::vector<double> reference(kValuesPerNode * mesh_.n_nodes(), 0.0);
  pairs_ = find_pairs(reference);
  accepted_pairs_ = pairs_;
  declared_ = reachable_pairs(reference);
  declared_grew_ = true;
}

std::vector<Vec3d> SurfaceContact::positions(std::span<const double> x) const {
  std::vector<Vec3d> points(mesh_.n_nodes(), Vec3d::Zero());
  for (const auto* list : {&facets_, &own_facets_})
    for (const auto& f : *list)
      for (int v : f) points[v] = deformed_position(mesh_, x, v);
  return points;
}

bool SurfaceContact::excluded(size_t i, int f) const {
  return std::binary_search(excluded_[i].begin(), excluded_[i].end(), f);
}

std::vector<int> SurfaceContact::find_pairs(std::span<const double> x,
                                            std::span<const int> keep) const {
  const std::vector<Vec3d> points = positions(x);
  const double reach = settings_.search_distance;
  const FacetSearch search(facets_, points, reach + widest_offset_);
  std::vector<int> out(nodes_.size(), -1);
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const Vec3d& xs = points[nodes_[i]];
    Vec3d normal = Vec3d::Zero();  // the node's own outward normal: the facets must face it
    for (int f : node_faces_[i]) normal += facet_normal(own_facets_[f], points);
    // The distance |g| to facet f when it qualifies (N4), else a negative number.
    const auto distance = [&](int f) {
      if (excluded(i, f)) return -1.0;
      const auto& t = facets_[f];
      const NodeFacetGap gap = node_facet_gap(xs, points[t[0]], points[t[1]], points[t[2]], false);
      const double g = gap.g - offset(i, f);
      if (gap.xi.minCoeff() < -kInside || gap.n.dot(normal) >= 0.0 || std::abs(g) > reach)
        return -1.0;
      return std::abs(g);
    };
    // A pair that still qualifies is kept, so that a node near the edge between two facets
    // does not switch back and forth between solves.
    if (!keep.empty() && keep[i] >= 0 && distance(keep[i]) >= 0.0) {
      out[i] = keep[i];
      continue;
    }
    double best = reach;
    for (int f : search.containing(xs)) {
      const double d = distance(f);
      if (d < 0.0 || d > best) continue;
      best = d;
      out[i] = f;
    }
  }
  return out;
}

NodeFacetGap SurfaceContact::gap(size_t i, int facet, std::span<const double> x,
                                 bool with_hessian) const {
  const auto& t = facets_[facet];
  return node_facet_gap(deformed_position(mesh_, x, nodes_[i]), deformed_position(mesh_, x, t[0]),
                        deformed_position(mesh_, x, t[1]), deformed_position(mesh_, x, t[2]),
                        with_hessian);
}

std::vector<SurfaceContact::Contact> SurfaceContact::contacts(std::span<const double> x) const {
  const double eps = settings_.penalty;
  std::vector<Contact> out(nodes_.size());
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const int f = pairs_[i];
    if (f < 0) continue;
    const NodeFacetGap g = gap(i, f, x, false);
    const double g_faces = g.g - offset(i, f);  // N14; the plane's distance on a solid
    out[i] = {f, g_faces, std::max(0.0, multipliers_[i] - eps * g_faces), g.n};
  }
  return out;
}

double SurfaceContact::largest_penetration(const std::vector<Contact>& contacts) {
  double worst = 0.0;
  for (const Contact& c : contacts)
    if (c.facet >= 0) worst = std::max(worst, -c.gap);
  return worst;
}

void SurfaceContact::assemble(double, std::span<const double> x, std::span<double> residual,
                              TangentSink* tangent) {
  const std::vector<Contact> cs = contacts(x);
  const double eps = settings_.penalty;
  Eigen::Matrix<double, 12, 12, Eigen::RowMajor> K;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const Contact& c = cs[i];
    if (c.lambda_hat <= 0.0) continue;
    const auto& t = facets_[c.facet];
    const std::array<int, 4> nodes = {nodes_[i], t[0], t[1], t[2]};
    const NodeFacetGap g = gap(i, c.facet, x, tangent != nullptr);
    // Pi = A/(2 eps) (lambda_hat^2 - lambda^2): r += -A lambda_hat dg/dx   (N2)
    const double A = areas_[i];
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 3; ++k)
        residual[node_dof(nodes[a], k)] -= A * c.lambda_hat * g.gradient[3 * a + k];
    if (!tangent) continue;
    // K = A (eps dg/dx dg/dx^T - lambda_hat d2g/dx2)   (N3)
    K = A * (eps * g.gradient * g.gradient.transpose() - c.lambda_hat * g.hessian);
    // Blocks between the node and a facet node go in only when declared (N6); the facet's own
    // nodes share a tetrahedron and are always coupled.
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        if ((a == 0) != (b == 0) && !declared_.count({nodes[0], nodes[a == 0 ? b : a]})) continue;
        std::array<int, 3> rows, cols;
        std::array<double, 9> block;
        for (int k = 0; k < 3; ++k) {
          rows[k] = node_dof(nodes[a], k);
          cols[k] = node_dof(nodes[b], k);
          for (int l = 0; l < 3; ++l) block[3 * k + l] = K(3 * a + k, 3 * b + l);
        }
        tangent->add(rows, cols, block);
      }
  }
}

std::set<std::pair<int, int>> SurfaceContact::reachable_pairs(std::span<const double> x) const {
  const std::vector<Vec3d> points = positions(x);
  std::set<std::pair<int, int>> out;
  // Twice the reach: a node pairs with the facets within its reach, and may move by as much
  // again before the next accepted step (N6); on a shell, beyond the faces' offsets (N14).
  const FacetSearch search(facets_, points, 2.0 * settings_.search_distance + widest_offset_);
  for (size_t i = 0; i < nodes_.size(); ++i) {
    for (int f : search.containing(points[nodes_[i]])) {
      if (excluded(i, f)) continue;
      for (int v : facets_[f]) out.insert({nodes_[i], v});
    }
  }
  return out;
}

void SurfaceContact::add_couplings(std::vector<std::pair<int, int>>& pairs) const {
  for (const auto& [s, m] : declared_)
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) {
        pairs.emplace_back(node_dof(s, k), node_dof(m, l));
        pairs.emplace_back(node_dof(m, l), node_dof(s, k));
      }
}

bool SurfaceContact::couplings_changed() {
  const bool grew = declared_grew_;
  declared_grew_ = false;
  return grew;
}

bool SurfaceContact::update_multipliers(std::span<const double> x) {
  const std::vector<Contact> cs = contacts(x);
  bool again = false;
  if (largest_penetration(cs) > settings_.tolerance) {
    // lambda <- max(0, lambda - eps g) = lambda_hat; 0 without a facet   (N5)
    for (size_t i = 0; i < nodes_.size(); ++i) multipliers_[i] = cs[i].lambda_hat;
    again = true;
  }
  // The pairs were held during the iterations; where the converged state pairs a node
  // differently and the node carries a force with either pair, the step is solved again with
  // the new pairs (N4). A node without force under both changes nothing in the residual.
  const std::vector<Contact> before = contacts(x);
  pairs_ = find_pairs(x, pairs_);
  const std::vector<Contact> after = contacts(x);
  for (size_t i = 0; i < nodes_.size(); ++i)
    if (before[i].facet != after[i].facet &&
        (before[i].lambda_hat > 0.0 || after[i].lambda_hat > 0.0))
      again = true;
  return again;
}

void SurfaceContact::accept_step(std::span<const double> x) {
  accepted_ = multipliers_;
  accepted_pairs_ = pairs_;
  // Pairs the body can reach from here join the sparsity (N6); none ever leaves it.
  for (const auto& pair : reachable_pairs(x))
    if (declared_.insert(pair).second) declared_grew_ = true;
}

void SurfaceContact::reject_step() {
  multipliers_ = accepted_;
  pairs_ = accepted_pairs_;
}

std::vector<double> SurfaceContact::save_state() const {
  std::vector<double> out(accepted_);
  out.insert(out.end(), accepted_pairs_.begin(), accepted_pairs_.end());
  out.push_back(static_cast<double>(declared_.size()));
  for (const auto& [s, m] : declared_) {
    out.push_back(s);
    out.push_back(m);
  }
  return out;
}

void SurfaceContact::load_state(std::span<const double> state) {
  const size_t n = nodes_.size();
  PLISSE_CHECK(
      state.size() > 2 * n && state.size() == 2 * n + 1 + 2 * static_cast<size_t>(state[2 * n]),
      "contact '" << settings_.name << "': the checkpoint does not fit this contact ("
                  << state.size() << " values for " << n << " contact nodes)");
  accepted_.assign(state.begin(), state.begin() + n);
  multipliers_ = accepted_;
  accepted_pairs_.assign(state.begin() + n, state.begin() + 2 * n);
  pairs_ = accepted_pairs_;
  declared_.clear();
  for (size_t k = 2 * n + 1; k + 1 < state.size(); k += 2)
    declared_.insert({static_cast<int>(state[k]), static_cast<int>(state[k + 1])});
  declared_grew_ = true;
}

std::vector<std::string> SurfaceContact::history_columns() const {
  const std::string& n = settings_.name;
  return {"force_x:" + n, "force_y:" + n, "force_z:" + n, "contact_nodes:" + n, "penetration:" + n};
}

std::vector<double> SurfaceContact::history_values(double, std::span<const double> x) const {
  const Vec3d f = force(x);
  return {f[0], f[1], f[2], static_cast<double>(n_contact_nodes(x)), penetration(x)};
}

std::vector<NodeField> SurfaceContact::node_fields(double, std::span<const double> x,
                                                   int n_nodes) const {
  NodeField field{"contact_" + settings_.name, std::vector<double>(n_nodes, 0.0)};
  const std::vector<Contact> cs = contacts(x);
  for (size_t i = 0; i < nodes_.size(); ++i) field.values[nodes_[i]] = cs[i].lambda_hat;
  return {field};
}

Vec3d SurfaceContact::force(std::span<const double> x) const {
  // F = sum of A lambda_hat n over the nodes in contact: the push of the facets on the nodes
  // (N7)
  const std::vector<Contact> cs = contacts(x);
  Vec3d sum = Vec3d::Zero();
  for (size_t i = 0; i < nodes_.size(); ++i) sum += areas_[i] * cs[i].lambda_hat * cs[i].normal;
  return sum;
}

double SurfaceContact::penetration(std::span<const double> x) const {
  return largest_penetration(contacts(x));
}

int SurfaceContact::n_contact_nodes(std::span<const double> x) const {
  int n = 0;
  for (const Contact& c : contacts(x)) n += c.lambda_hat > 0.0;
  return n;
}

}  // namespace plisse
