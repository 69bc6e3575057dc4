#include "mesh/quality.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "mesh/topology.hpp"

namespace plisse {
namespace {

constexpr int kMaxMessages = 10;

/// Collects messages of one kind, keeping the first kMaxMessages and counting the rest.
class MessageList {
 public:
  MessageList(std::vector<std::string>& out, std::string summary)
      : out_(out), summary_(std::move(summary)) {}
  ~MessageList() {
    if (count_ > kMaxMessages)
      out_.push_back("... and " + std::to_string(count_ - kMaxMessages) + " more " + summary_);
  }
  MessageList(const MessageList&) = delete;
  MessageList& operator=(const MessageList&) = delete;
  void add(const std::string& message) {
    if (count_++ < kMaxMessages) out_.push_back(message);
  }

 private:
  std::vector<std::string>& out_;
  std::string summary_;
  int count_ = 0;
};

std::string number(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

/// " (centred at [x, y, z])": where an element of a message lies, for a mesh viewer.
std::string centred_at(const Vec3d& c) {
  return " (centred at [" + number(c.x()) + ", " + number(c.y()) + ", " + number(c.z()) + "])";
}

/// (longest edge / inradius) / (2 sqrt 6), inradius r = 3 V / (sum of face areas); 1 for a
/// regular tetrahedron, infinity for a degenerate one.
double aspect_ratio(const std::array<Vec3d, 4>& x, double volume) {
  double longest = 0.0;
  for (const auto& e : kTetEdges)
    longest = std::max(
        longest, (x[static_cast<std::size_t>(e[0])] - x[static_cast<std::size_t>(e[1])]).norm());
  double area = 0.0;
  for (const auto& f : kTetFaces)
    area += 0.5 * (x[static_cast<std::size_t>(f[1])] - x[static_cast<std::size_t>(f[0])])
                      .cross(x[static_cast<std::size_t>(f[2])] - x[static_cast<std::size_t>(f[0])])
                      .norm();
  const double inradius = 3.0 * std::abs(volume) / area;
  if (!(inradius > 0.0)) return std::numeric_limits<double>::infinity();
  return longest / inradius / (2.0 * std::sqrt(6.0));
}

void check_tag_indices(const std::map<std::string, std::vector<int>>& tags, std::size_t n,
                       const char* kind, MessageList& errors) {
  for (const auto& [name, indices] : tags)
    for (int i : indices)
      if (i < 0 || static_cast<std::size_t>(i) >= n) {
        errors.add("tag '" + name + "' lists " + kind + " " + std::to_string(i) +
                   ", which does not exist (" + std::to_string(n) + " " + kind + "s)");
        break;
      }
}

/// Every node index of the elements and triangles exists, and a second-order mesh has one set of
/// edge nodes per tetrahedron. False (with the errors in `report`) otherwise.
bool check_node_indices(const Mesh& mesh, MeshReport& report) {
  const int n_nodes = mesh.n_nodes();
  MessageList errors(report.errors, "tetrahedra with node indices out of range");
  bool bad = false;
  auto check = [&](int node, const std::string& where) {
    if (node >= 0 && node < n_nodes) return;
    errors.add(where + " references node " + std::to_string(node) + ", which does not exist (" +
               std::to_string(n_nodes) + " nodes)");
    bad = true;
  };
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int n : mesh.tets[t]) check(n, "tetrahedron " + std::to_string(t));
  for (std::size_t t = 0; t < mesh.tet_edge_nodes.size(); ++t)
    for (int n : mesh.tet_edge_nodes[t])
      check(n, "tetrahedron " + std::to_string(t) + " (edge node)");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int n : mesh.triangles[t]) check(n, "triangle " + std::to_string(t));
  for (std::size_t t = 0; t < mesh.triangle_edge_nodes.size(); ++t)
    for (int n : mesh.triangle_edge_nodes[t])
      check(n, "triangle " + std::to_string(t) + " (edge node)");
  if (!mesh.tet_edge_nodes.empty() && mesh.tet_edge_nodes.size() != mesh.tets.size()) {
    errors.add("second-order mesh: " + std::to_string(mesh.tet_edge_nodes.size()) +
               " edge-node sets for " + std::to_string(mesh.tets.size()) + " tetrahedra");
    bad = true;
  }
  return !bad;
}

/// Every coordinate is a finite number: NaN or infinite coordinates (e.g. "nan" in a .msh file)
/// make every volume test false, so such a mesh would pass them. And none beyond
/// kMaxCoordinate: volumes (cubes of lengths) and the tangent's products of them overflow to
/// infinity long before a coordinate does. False otherwise.
bool check_finite_coordinates(const Mesh& mesh, MeshReport& report) {
  const int n_nodes = mesh.n_nodes();
  {
    MessageList errors(report.errors, "nodes with non-finite coordinates");
    for (int i = 0; i < n_nodes; ++i)
      if (!mesh.nodes[static_cast<std::size_t>(i)].allFinite()) {
        const Vec3d& x = mesh.nodes[static_cast<std::size_t>(i)];
        errors.add("node " + std::to_string(i) + " has a coordinate that is not a finite number (" +
                   number(x.x()) + ", " + number(x.y()) + ", " + number(x.z()) + ")");
      }
  }
  if (!report.errors.empty()) return false;
  MessageList errors(report.errors, "nodes beyond the coordinate range");
  bool inside = true;
  for (int i = 0; i < n_nodes; ++i) {
    const Vec3d& x = mesh.nodes[static_cast<std::size_t>(i)];
    if (x.cwiseAbs().maxCoeff() <= kMaxCoordinate) continue;
    // The reason once, with the first node.
    errors.add("node " + std::to_string(i + 1) + " (1-based) lies at (" + number(x.x()) + ", " +
               number(x.y()) + ", " + number(x.z()) + "), beyond ±" + number(kMaxCoordinate) +
               " mm" +
               (inside ? ": volumes and stiffnesses of such a body overflow double precision (a "
                         "mesh in other units must be rescaled)"
                       : ""));
    inside = false;
  }
  return inside;
}

/// The volume of every tetrahedron: none degenerate or inverted; its smallest volume and largest
/// aspect ratio, and a warning for stretched ones.
void check_volumes(const Mesh& mesh, MeshReport& report) {
  report.min_volume = mesh.tets.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  {
    MessageList inverted(report.errors,
                         "inverted or degenerate tetrahedra (counted from 1 in the mesh's order)");
    int n_stretched = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const auto& n = mesh.tets[t];
      const std::array<Vec3d, 4> x = {
          mesh.nodes[static_cast<std::size_t>(n[0])], mesh.nodes[static_cast<std::size_t>(n[1])],
          mesh.nodes[static_cast<std::size_t>(n[2])], mesh.nodes[static_cast<std::size_t>(n[3])]};
      const double volume = six_signed_volume(x[0], x[1], x[2], x[3]) / 6.0;
      report.min_volume = std::min(report.min_volume, volume);
      double longest = 0.0;
      for (const auto& e : kTetEdges)
        longest = std::max(
            longest,
            (x[static_cast<std::size_t>(e[0])] - x[static_cast<std::size_t>(e[1])]).norm());
      // Degenerate: volume below 1e-12 of the cube of its longest edge (round-off level). Named
      // by its place among the tetrahedra counted from 1 and by its centre, which a user finds
      // in a mesh viewer.
      const auto which = [&] {
        return "tetrahedron " + std::to_string(t + 1) +
               centred_at(0.25 * (x[0] + x[1] + x[2] + x[3]));
      };
      if (std::abs(volume) <= 1e-12 * longest * longest * longest) {
        inverted.add(which() + " is degenerate (volume " + number(volume) + " mm^3)");
        continue;
      }
      if (volume < 0.0) {
        inverted.add(which() + " is inverted (volume " + number(volume) + " mm^3)");
        continue;
      }
      const double ar = aspect_ratio(x, volume);
      report.max_aspect_ratio = std::max(report.max_aspect_ratio, ar);
      if (ar > kAspectRatioWarning) ++n_stretched;
    }
    if (n_stretched > 0)
      report.warnings.push_back(
          std::to_string(n_stretched) + " tetrahedra have an aspect ratio above " +
          number(kAspectRatioWarning) + " (largest " + number(report.max_aspect_ratio) + ")");
  }
}

/// A face shared by two tetrahedra must separate them. Each tetrahedron may be
/// positively numbered while the two lie on the same side of their common face (a node dragged
/// through the opposite face): they overlap, and the element is inverted with respect to its
/// neighbour. Checked with the signs of 6V(face, opposite node) for both tetrahedra; a zero sign
/// (a degenerate tetrahedron, reported above) is not judged.
void check_folds(const Mesh& mesh, MeshReport& report) {
  MessageList errors(report.errors, "folded faces");
  std::vector<std::array<int, 4>> faces;  // sorted face nodes, then 4 * tet + local face
  faces.reserve(4 * mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (std::size_t f = 0; f < 4; ++f) {
      const auto& n = mesh.tets[t];
      const auto key = sorted_face({n[static_cast<std::size_t>(kTetFaces[f][0])],
                                    n[static_cast<std::size_t>(kTetFaces[f][1])],
                                    n[static_cast<std::size_t>(kTetFaces[f][2])]});
      faces.push_back({key[0], key[1], key[2], static_cast<int>(4 * t + f)});
    }
  std::sort(faces.begin(), faces.end());
  // 6V of (sorted face, node opposite local face f of tet t); the sign tells the side.
  const auto side = [&](const std::array<int, 4>& face) {
    const std::size_t t = static_cast<std::size_t>(face[3] / 4),
                      f = static_cast<std::size_t>(face[3] % 4);
    const int opposite = mesh.tets[t][static_cast<std::size_t>(6 - kTetFaces[f][0] -
                                                               kTetFaces[f][1] - kTetFaces[f][2])];
    const auto x = [&](int v) { return mesh.nodes[static_cast<std::size_t>(v)]; };
    return six_signed_volume(x(face[0]), x(face[1]), x(face[2]), x(opposite));
  };
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && std::equal(faces[j].begin(), faces[j].begin() + 3, faces[i].begin()))
      ++j;
    const std::string nodes = std::to_string(faces[i][0]) + ", " + std::to_string(faces[i][1]) +
                              ", " + std::to_string(faces[i][2]);
    if (j - i > 2) {
      errors.add("face (" + nodes + ") is shared by " + std::to_string(j - i) +
                 " tetrahedra (at most 2)");
    } else if (j - i == 2) {
      const double s0 = side(faces[i]), s1 = side(faces[i + 1]);
      if ((s0 > 0.0 && s1 > 0.0) || (s0 < 0.0 && s1 < 0.0))
        errors.add("tetrahedra " + std::to_string(faces[i][3] / 4) + " and " +
                   std::to_string(faces[i + 1][3] / 4) +
                   " lie on the same side of their common face (" + nodes +
                   "): they overlap, the mesh is folded (an inverted element)");
    }
    i = j;
  }
}

/// Nodes that no tetrahedron uses carry no stiffness: counted, with a warning.
void check_unused_nodes(const Mesh& mesh, MeshReport& report) {
  const int n_nodes = mesh.n_nodes();
  std::vector<char> used(static_cast<std::size_t>(n_nodes), 0);
  for (const auto& t : mesh.tets)
    for (int n : t) used[static_cast<std::size_t>(n)] = 1;
  for (const auto& t : mesh.tet_edge_nodes)
    for (int n : t) used[static_cast<std::size_t>(n)] = 1;
  std::string first;
  for (int i = 0; i < n_nodes; ++i)
    if (!used[static_cast<std::size_t>(i)]) {
      if (report.n_unused_nodes < 5)
        first += (report.n_unused_nodes ? ", " : "") + std::to_string(i);
      ++report.n_unused_nodes;
    }
  if (report.n_unused_nodes > 0)
    report.warnings.push_back(std::to_string(report.n_unused_nodes) +
                              " nodes are used by no tetrahedron (first: " + first +
                              "); they carry no stiffness");
}

/// Second-order meshes: every edge has one edge node, whichever tetrahedron names it.
void check_edge_nodes(const Mesh& mesh, MeshReport& report) {
  MessageList errors(report.errors, "inconsistent edge nodes");
  std::vector<std::array<int, 4>> edges;  // (a, b, mid, tet) with a < b
  edges.reserve(6 * mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (std::size_t e = 0; e < 6; ++e) {
      const int a = mesh.tets[t][static_cast<std::size_t>(kTetEdges[e][0])];
      const int b = mesh.tets[t][static_cast<std::size_t>(kTetEdges[e][1])];
      edges.push_back(
          {std::min(a, b), std::max(a, b), mesh.tet_edge_nodes[t][e], static_cast<int>(t)});
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (edges[i][0] == edges[i - 1][0] && edges[i][1] == edges[i - 1][1] &&
        edges[i][2] != edges[i - 1][2])
      errors.add("edge (" + std::to_string(edges[i][0]) + ", " + std::to_string(edges[i][1]) +
                 ") has different edge nodes in tetrahedra " + std::to_string(edges[i - 1][3]) +
                 " and " + std::to_string(edges[i][3]));
}

/// The tags list existing triangles and tetrahedra, and every required tag exists and is not empty.
void check_tags(const Mesh& mesh, const std::vector<std::string>& required_tags,
                MeshReport& report) {
  MessageList errors(report.errors, "tag problems");
  check_tag_indices(mesh.surface_tags, mesh.triangles.size(), "triangle", errors);
  check_tag_indices(mesh.volume_tags, mesh.tets.size(), "tetrahedron", errors);
  for (const auto& name : required_tags) {
    const auto s = mesh.surface_tags.find(name);
    const auto v = mesh.volume_tags.find(name);
    if (s == mesh.surface_tags.end() && v == mesh.volume_tags.end())
      errors.add("required tag '" + name + "' is missing");
    else if ((s == mesh.surface_tags.end() || s->second.empty()) &&
             (v == mesh.volume_tags.end() || v->second.empty()))
      errors.add("required tag '" + name + "' is empty");
  }
}

/// Every triangle is a face of a tetrahedron; a warning for triangles between two tetrahedra.
void check_triangles_are_faces(const Mesh& mesh, MeshReport& report) {
  std::vector<std::array<int, 3>> all_faces;
  all_faces.reserve(4 * mesh.tets.size());
  for (const auto& n : mesh.tets)
    for (const auto& f : kTetFaces)
      all_faces.push_back(
          sorted_face({n[static_cast<std::size_t>(f[0])], n[static_cast<std::size_t>(f[1])],
                       n[static_cast<std::size_t>(f[2])]}));
  std::sort(all_faces.begin(), all_faces.end());
  MessageList errors(report.errors, "triangles that are not faces of the tetrahedra");
  int n_interior = 0;
  std::string first_interior;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto key = sorted_face(mesh.triangles[i]);
    const auto range = std::equal_range(all_faces.begin(), all_faces.end(), key);
    const auto count = range.second - range.first;
    if (count == 0) {
      errors.add("triangle " + std::to_string(i) + " (nodes " +
                 std::to_string(mesh.triangles[i][0]) + ", " +
                 std::to_string(mesh.triangles[i][1]) + ", " +
                 std::to_string(mesh.triangles[i][2]) + ") is not a face of any tetrahedron");
    } else if (count > 1) {
      if (n_interior++ == 0) first_interior = std::to_string(i);
    }
  }
  if (n_interior > 0)
    report.warnings.push_back(std::to_string(n_interior) + " triangles (first: " + first_interior +
                              ") are interior faces between two tetrahedra, not on the boundary");
}

/// Each edge of the closed boundary surface must be shared by
/// exactly two boundary faces.
void check_boundary_manifold(const std::vector<BoundaryFace>& boundary, MeshReport& report) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * boundary.size());
  for (const auto& f : boundary)
    for (int k = 0; k < 3; ++k) {
      const int a = f.nodes[static_cast<std::size_t>(k)],
                b = f.nodes[static_cast<std::size_t>((k + 1) % 3)];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  MessageList errors(report.errors, "non-manifold boundary edges");
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2)
      errors.add("boundary edge (" + std::to_string(edges[i].first) + ", " +
                 std::to_string(edges[i].second) + ") is shared by " + std::to_string(j - i) +
                 " boundary faces (non-manifold; expected 2)");
    i = j;
  }
}

}  // namespace

/// The triangles of a shell mesh: none degenerate; the smallest angle and the largest turn
/// between neighbours, with warnings (kShellAngleWarning, kShellTurnWarning); nodes of no
/// triangle; tags within range.
void check_shell_surface(const Mesh& mesh, MeshReport& report) {
  MessageList degenerate(report.errors,
                         "degenerate triangles (counted from 1 in the mesh's order)");
  const double kDegree = 180.0 / std::acos(-1.0);
  std::vector<Vec3d> normals(mesh.triangles.size(), Vec3d::Zero());
  report.min_angle_deg = 180.0;
  int n_sharp = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3d n =
        (mesh.nodes[tri[1]] - mesh.nodes[tri[0]]).cross(mesh.nodes[tri[2]] - mesh.nodes[tri[0]]);
    double longest = 0.0;
    for (int a = 0; a < 3; ++a) {
      const Vec3d u = mesh.nodes[tri[(a + 1) % 3]] - mesh.nodes[tri[a]];
      const Vec3d v = mesh.nodes[tri[(a + 2) % 3]] - mesh.nodes[tri[a]];
      longest = std::max(longest, u.norm());
      const double angle = std::atan2(u.cross(v).norm(), u.dot(v)) * kDegree;
      report.min_angle_deg = std::min(report.min_angle_deg, angle);
      if (angle < kShellAngleWarning) ++n_sharp;
    }
    if (n.norm() <= 2e-12 * longest * longest) {
      degenerate.add(
          "triangle " + std::to_string(t + 1) +
          centred_at((mesh.nodes[tri[0]] + mesh.nodes[tri[1]] + mesh.nodes[tri[2]]) / 3.0) +
          " has zero area");
      continue;
    }
    normals[t] = n.normalized();
  }
  if (mesh.triangles.empty()) report.min_angle_deg = 0.0;
  int n_turned = 0;
  for (std::size_t t = 0; t < mesh.triangle_neighbours.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int across = mesh.triangle_neighbours[t][i];
      if (across < 0) continue;
      // The neighbour is the triangle with the node `across` and this side's two nodes.
      const int a = mesh.triangles[t][(i + 1) % 3], b = mesh.triangles[t][(i + 2) % 3];
      const Vec3d& xa = mesh.nodes[a];
      const Vec3d other = (mesh.nodes[b] - xa).cross(mesh.nodes[across] - xa);
      if (other.norm() == 0.0 || normals[t].norm() == 0.0) continue;
      // The neighbour runs through the side from b to a: its normal is (x_b - x_a) x (x_c - x_a)
      // turned, i.e. -(other) when it is oriented like this triangle.
      const double turn =
          std::acos(std::clamp(normals[t].dot(-other.normalized()), -1.0, 1.0)) * kDegree;
      report.max_turn_deg = std::max(report.max_turn_deg, turn);
      if (turn > kShellTurnWarning) ++n_turned;
    }
  if (n_sharp > 0)
    report.warnings.push_back(std::to_string(n_sharp) + " triangle angles are below " +
                              number(kShellAngleWarning) + " degrees (smallest " +
                              number(report.min_angle_deg) + ")");
  if (n_turned > 0)
    report.warnings.push_back(
        std::to_string(n_turned / 2) + " sides turn the surface by more than " +
        number(kShellTurnWarning) + " degrees (largest " + number(report.max_turn_deg) +
        "): the shell triangle reads its curvature from its neighbours and smooths such a crease; "
        "refine there");
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const auto& tri : mesh.triangles)
    for (int v : tri) used[static_cast<std::size_t>(v)] = 1;
  report.n_unused_nodes = static_cast<int>(std::count(used.begin(), used.end(), 0));
  if (report.n_unused_nodes > 0)
    report.warnings.push_back(std::to_string(report.n_unused_nodes) +
                              " nodes are used by no triangle; they carry no stiffness");
  MessageList tags(report.errors, "tag problems");
  check_tag_indices(mesh.surface_tags, mesh.triangles.size(), "triangle", tags);
  check_tag_indices(mesh.edge_tags, mesh.edges.size(), "edge", tags);
}

MeshReport check_mesh(const Mesh& mesh, const std::vector<std::string>& required_tags) {
  MeshReport report;
  // The checks after these two index nodes and compute with coordinates.
  if (!check_node_indices(mesh, report) || !check_finite_coordinates(mesh, report)) return report;
  if (mesh.is_shell()) {
    check_shell_surface(mesh, report);
    return report;
  }
  if (mesh.tets.empty()) report.errors.push_back("the mesh has no tetrahedra");
  check_volumes(mesh, report);
  check_folds(mesh, report);
  check_unused_nodes(mesh, report);
  if (!mesh.tet_edge_nodes.empty()) check_edge_nodes(mesh, report);
  check_tags(mesh, required_tags, report);
  const auto boundary = compute_boundary_faces(mesh);
  report.n_boundary_faces = static_cast<int>(boundary.size());
  check_triangles_are_faces(mesh, report);
  check_boundary_manifold(boundary, report);
  return report;
}

}  // namespace plisse
