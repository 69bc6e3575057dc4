#include "mesh/imperfection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "mesh/quality.hpp"
#include "mesh/topology.hpp"

namespace plisse {
namespace {

/// Uniform grid over a bounding box holding point indices, for nearest-point queries.
/// Cells are cubes of side h with h^3 = (box volume) / n_points, so a cell holds O(1) points on
/// average for a volume cloud and O((R/h)^(2/3)) for a surface cloud of size R: both cheap.
class PointGrid {
 public:
  /// `points`: all candidate positions; `box_lo`, `box_hi`: a box containing every point and
  /// every later query point.
  PointGrid(const std::vector<Vec3d>& points, const Vec3d& box_lo, const Vec3d& box_hi)
      : points_(points), lo_(box_lo) {
    const Vec3d extent = (box_hi - box_lo).cwiseMax(1e-12 * (box_hi - box_lo).norm() + 1e-300);
    const double n = static_cast<double>(std::max<std::size_t>(points.size(), 1));
    h_ = std::cbrt(extent.prod() / n);
    // No axis gets more than 2^10 cells, nor more than the point count allows (flat boxes).
    for (int i = 0; i < 3; ++i) {
      const double cells = std::clamp(std::ceil(extent[i] / h_), 1.0, std::min(1024.0, n));
      dims_[i] = static_cast<int>(cells);
    }
    h_ = std::max({extent[0] / dims_[0], extent[1] / dims_[1], extent[2] / dims_[2]});
    start_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    std::vector<int> cell_of(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      cell_of[k] = flat(cell(points[k]));
      ++start_[static_cast<std::size_t>(cell_of[k]) + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(points.size());
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < points.size(); ++k)
      items_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_of[k])]++)] =
          static_cast<int>(k);
  }

  /// Index of the point nearest to x; on equal distance the lower index. Rings of cells at
  /// Chebyshev distance r = 0, 1, 2, ... around x's cell are visited until no unvisited cell can
  /// hold a point closer than the best found: every cell of ring r + 1 is at least r h from x
  /// (strictly closer is required, so an equally distant lower index is never missed).
  int nearest(const Vec3d& x) const {
    const std::array<int, 3> c = cell(x);
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    const int max_ring = std::max({dims_[0], dims_[1], dims_[2]});
    for (int r = 0; r <= max_ring; ++r) {
      for (int i = c[0] - r; i <= c[0] + r; ++i)
        for (int j = c[1] - r; j <= c[1] + r; ++j)
          for (int k = c[2] - r; k <= c[2] + r; ++k) {
            const bool on_ring =
                std::abs(i - c[0]) == r || std::abs(j - c[1]) == r || std::abs(k - c[2]) == r;
            if (!on_ring || i < 0 || j < 0 || k < 0 || i >= dims_[0] || j >= dims_[1] ||
                k >= dims_[2])
              continue;
            const int f = flat({i, j, k});
            for (int s = start_[static_cast<std::size_t>(f)];
                 s < start_[static_cast<std::size_t>(f) + 1]; ++s) {
              const int p = items_[static_cast<std::size_t>(s)];
              const double d2 = (points_[static_cast<std::size_t>(p)] - x).squaredNorm();
              if (d2 < best_d2 || (d2 == best_d2 && p < best)) {
                best_d2 = d2;
                best = p;
              }
            }
          }
      if (best >= 0 && std::sqrt(best_d2) < r * h_) break;
    }
    return best;
  }

 private:
  std::array<int, 3> cell(const Vec3d& x) const {
    std::array<int, 3> c{};
    for (int i = 0; i < 3; ++i)
      c[static_cast<std::size_t>(i)] =
          std::clamp(static_cast<int>(std::floor((x[i] - lo_[i]) / h_)), 0, dims_[i] - 1);
    return c;
  }
  int flat(const std::array<int, 3>& c) const { return (c[2] * dims_[1] + c[1]) * dims_[0] + c[0]; }

  const std::vector<Vec3d>& points_;
  Vec3d lo_;
  double h_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_;  // CSR: items_[start_[c] .. start_[c + 1]) are the points of cell c
  std::vector<int> items_;
};

/// `triangles` oriented outward: each is looked up among `faces`, the boundary faces of the
/// tetrahedra (compute_boundary_faces: outward, sorted by sorted_face).
std::vector<std::array<int, 3>> orient_outward(const Mesh& mesh,
                                               const std::vector<BoundaryFace>& faces,
                                               std::span<const std::array<int, 3>> triangles,
                                               const std::string& what) {
  std::vector<std::array<int, 3>> out;
  out.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int n : triangles[t])
      PLISSE_CHECK(n >= 0 && n < mesh.n_nodes(), "imperfection: " << what << " triangle " << t
                                                                  << " refers to node " << n
                                                                  << ", which does not exist");
    const std::array<int, 3> key = sorted_face(triangles[t]);
    const auto it = std::lower_bound(faces.begin(), faces.end(), key,
                                     [](const BoundaryFace& f, const std::array<int, 3>& k) {
                                       return sorted_face(f.nodes) < k;
                                     });
    PLISSE_CHECK(it != faces.end() && sorted_face(it->nodes) == key,
                 "imperfection: " << what << " triangle " << t << " (nodes " << key[0] << ", "
                                  << key[1] << ", " << key[2]
                                  << ") is not a boundary face of the tetrahedra");
    out.push_back(it->nodes);
  }
  return out;
}

Vec3d area_normal(const Mesh& mesh, const std::array<int, 3>& t) {
  const Vec3d& x0 = mesh.nodes[static_cast<std::size_t>(t[0])];
  return (mesh.nodes[static_cast<std::size_t>(t[1])] - x0)
      .cross(mesh.nodes[static_cast<std::size_t>(t[2])] - x0);
}

/// Unit normal of a planar tag; plisse::Error if the tag is missing, empty or not planar.
Vec3d plane_normal(const Mesh& mesh, const std::vector<BoundaryFace>& faces, const std::string& tag,
                   double length_scale) {
  const auto it = mesh.surface_tags.find(tag);
  PLISSE_CHECK(it != mesh.surface_tags.end() && !it->second.empty(),
               "imperfection: planar surface '" << tag << "' does not exist or is empty");
  std::vector<std::array<int, 3>> triangles;
  for (int t : it->second) {
    PLISSE_CHECK(
        t >= 0 && static_cast<std::size_t>(t) < mesh.triangles.size(),
        "imperfection: surface '" << tag << "' lists triangle " << t << ", which does not exist");
    triangles.push_back(mesh.triangles[static_cast<std::size_t>(t)]);
  }
  const auto oriented = orient_outward(mesh, faces, triangles, "surface '" + tag + "'");
  Vec3d n = Vec3d::Zero();
  for (const auto& t : oriented) n += area_normal(mesh, t);
  PLISSE_CHECK(n.norm() > 0.0, "imperfection: surface '" << tag << "' has no area");
  n.normalize();
  const Vec3d& x0 = mesh.nodes[static_cast<std::size_t>(oriented.front()[0])];
  for (const auto& t : oriented)
    for (int v : t) {
      const double distance = std::abs(n.dot(mesh.nodes[static_cast<std::size_t>(v)] - x0));
      PLISSE_CHECK(distance <= 1e-9 * length_scale,
                   "imperfection: surface '" << tag << "' is not planar (node " << v << " is "
                                             << distance << " mm off its plane)");
    }
  return n;
}

}  // namespace

double seeded_unit_value(std::uint64_t engine_output) {
  // (u >> 11) is an integer in [0, 2^53): exact in a double, and so is the product and the sum.
  return static_cast<double>(engine_output >> 11) * 0x1.0p-52 - 1.0;
}

std::vector<Vec3d> compute_random_imperfection(const Mesh& mesh,
                                               std::span<const std::array<int, 3>> outer_triangles,
                                               double amplitude, std::uint64_t seed,
                                               const std::vector<std::string>& planar_tags,
                                               const std::vector<HeldPlane>& held_planes) {
  PLISSE_CHECK(std::isfinite(amplitude) && amplitude > 0.0,
               "imperfection: amplitude must be finite and > 0 (got " << amplitude << " mm)");
  PLISSE_CHECK(!outer_triangles.empty(), "imperfection: the outer surface has no triangles");
  const std::size_t n_nodes = mesh.nodes.size();
  Vec3d lo = Vec3d::Constant(std::numeric_limits<double>::infinity());
  Vec3d hi = -lo;
  for (const Vec3d& x : mesh.nodes) {
    PLISSE_CHECK(x.allFinite(), "imperfection: the mesh has a node with non-finite coordinates");
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double diameter = (hi - lo).norm();

  // Outer nodes (increasing index: the order of the draws) and their area-weighted normals. A
  // shell's mid-surface triangles are oriented consistently already (make_shell_surface) and
  // are no tetrahedron's faces (I1s).
  const bool shell = mesh.is_shell();
  PLISSE_CHECK(!shell || planar_tags.empty(),
               "imperfection: a shell's surface tags name its faces, not planes (give the "
               "nodes held in a symmetry plane as held planes)");
  const std::vector<BoundaryFace> faces =
      shell ? std::vector<BoundaryFace>{} : compute_boundary_faces(mesh);
  std::vector<std::array<int, 3>> oriented;
  if (shell) {
    for (std::size_t t = 0; t < outer_triangles.size(); ++t)
      for (int n : outer_triangles[t])
        PLISSE_CHECK(n >= 0 && n < mesh.n_nodes(), "imperfection: outer surface triangle "
                                                       << t << " refers to node " << n
                                                       << ", which does not exist");
    oriented.assign(outer_triangles.begin(), outer_triangles.end());
  } else {
    oriented = orient_outward(mesh, faces, outer_triangles, "outer surface");
  }
  std::vector<Vec3d> normal_of_node(n_nodes, Vec3d::Zero());
  for (const auto& t : oriented) {
    const Vec3d n = area_normal(mesh, t);  // |n| = 2 area: the weights of (I1)
    for (int v : t) normal_of_node[static_cast<std::size_t>(v)] += n;
  }
  std::vector<int> outer_nodes;
  for (std::size_t v = 0; v < n_nodes; ++v)
    if (!normal_of_node[v].isZero(0.0)) outer_nodes.push_back(static_cast<int>(v));
  PLISSE_CHECK(!outer_nodes.empty(), "imperfection: the outer surface has no area");

  std::mt19937_64 engine(seed);
  std::vector<Vec3d> outer_points, outer_shift;
  outer_points.reserve(outer_nodes.size());
  outer_shift.reserve(outer_nodes.size());
  for (int v : outer_nodes) {
    outer_points.push_back(mesh.nodes[static_cast<std::size_t>(v)]);
    outer_shift.push_back(seeded_unit_value(engine()) *
                          normal_of_node[static_cast<std::size_t>(v)].normalized());
  }

  // Every node takes the shift of its nearest outer node (columns move rigidly). On a shell
  // there is no wall to carry along: the outer nodes take their own shift, the others none.
  std::vector<Vec3d> d(n_nodes, Vec3d::Zero());
  if (shell) {
    for (std::size_t k = 0; k < outer_nodes.size(); ++k)
      d[static_cast<std::size_t>(outer_nodes[k])] = outer_shift[k];
  } else {
    const PointGrid grid(outer_points, lo, hi);
    for (std::size_t j = 0; j < n_nodes; ++j)
      d[j] = outer_shift[static_cast<std::size_t>(grid.nearest(mesh.nodes[j]))];
  }

  // Nodes on a symmetry plane stay in it (Π_j of I1).
  for (const std::string& tag : planar_tags) {
    const Vec3d n = plane_normal(mesh, faces, tag, diameter);
    std::vector<char> on_plane(n_nodes, 0);
    for (int t : mesh.surface_tags.at(tag))
      for (int v : mesh.triangles[static_cast<std::size_t>(t)])
        on_plane[static_cast<std::size_t>(v)] = 1;
    for (std::size_t j = 0; j < n_nodes; ++j)
      if (on_plane[j] != 0) d[j] -= n.dot(d[j]) * n;
  }
  for (const HeldPlane& plane : held_planes) {
    PLISSE_CHECK(plane.normal.allFinite() && plane.normal.norm() > 0.0,
                 "imperfection: a held plane has no normal");
    const Vec3d n = plane.normal.normalized();
    for (int v : plane.nodes) {
      PLISSE_CHECK(v >= 0 && v < mesh.n_nodes(),
                   "imperfection: a held plane lists node " << v << ", which does not exist");
      d[static_cast<std::size_t>(v)] -= n.dot(d[static_cast<std::size_t>(v)]) * n;
    }
  }

  // A second-order mesh: the field is that of the corners, interpolated linearly along each edge
  // (I1b), so the edge nodes keep the curved wall's shape and the perturbation has no kink
  // inside an element.
  for (std::size_t t = 0; t < mesh.tet_edge_nodes.size(); ++t)
    for (int k = 0; k < 6; ++k) {
      const auto [a, b] = kTetEdges[static_cast<std::size_t>(k)];
      const auto& tet = mesh.tets[t];
      d[static_cast<std::size_t>(mesh.tet_edge_nodes[t][static_cast<std::size_t>(k)])] =
          0.5 * (d[static_cast<std::size_t>(tet[static_cast<std::size_t>(a)])] +
                 d[static_cast<std::size_t>(tet[static_cast<std::size_t>(b)])]);
    }

  double largest = 0.0;
  for (const Vec3d& v : d) largest = std::max(largest, v.norm());
  PLISSE_CHECK(largest > 0.0,
               "imperfection: the random field vanishes (every outer node is held "
               "in a symmetry plane along its normal)");
  for (Vec3d& v : d) v *= amplitude / largest;
  return d;
}

std::vector<Vec3d> compute_mode_imperfection(const Mesh& mesh, std::span<const Vec3d> shape,
                                             double amplitude) {
  PLISSE_CHECK(std::isfinite(amplitude) && amplitude > 0.0,
               "imperfection: amplitude must be finite and > 0 (got " << amplitude << " mm)");
  PLISSE_CHECK(shape.size() == mesh.nodes.size(), "imperfection: the mode has "
                                                      << shape.size() << " nodal vectors, the mesh "
                                                      << mesh.nodes.size() << " nodes");
  double largest = 0.0;
  for (std::size_t j = 0; j < shape.size(); ++j) {
    PLISSE_CHECK(shape[j].allFinite(), "imperfection: the mode is not finite at node " << j);
    largest = std::max(largest, shape[j].norm());
  }
  PLISSE_CHECK(largest > 0.0, "imperfection: the mode is zero everywhere");
  std::vector<Vec3d> d(shape.begin(), shape.end());
  for (Vec3d& v : d) v *= amplitude / largest;
  return d;
}

void apply_imperfection(Mesh& mesh, std::span<const Vec3d> displacement) {
  PLISSE_CHECK(displacement.size() == mesh.nodes.size(),
               "imperfection: " << displacement.size() << " nodal displacements for a mesh of "
                                << mesh.nodes.size() << " nodes");
  double amplitude = 0.0;
  for (const Vec3d& v : displacement) {
    PLISSE_CHECK(v.allFinite(), "imperfection: a nodal displacement is not finite");
    amplitude = std::max(amplitude, v.norm());
  }
  std::vector<Vec3d> original = mesh.nodes;
  for (std::size_t j = 0; j < mesh.nodes.size(); ++j) mesh.nodes[j] += displacement[j];
  const MeshReport report = check_mesh(mesh);
  if (report.ok()) return;
  mesh.nodes = std::move(original);
  std::ostringstream message;
  message << "imperfection amplitude " << amplitude
          << " mm is too large for this mesh (reduce it): " << report.errors.front();
  throw Error(message.str());
}

}  // namespace plisse
