#include "physics/rigid_motion.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace plisse {
namespace {

using Vec6d = Eigen::Matrix<double, 6, 1>;
using Mat6d = Eigen::Matrix<double, 6, 6>;

/// A null vector below this (relative to the largest eigenvalue of the holds' Gram matrix) is free:
/// holds at nodes within about 1e-5 of a line (relative to the piece's size) leave the turn about
/// that line free, as the tangent's round-off would.
constexpr double kFree = 1e-10;
/// A candidate motion lies in the free space when this little of it is left out.
constexpr double kInside = 1e-6;

std::string direction_text(Vec3d d) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(d[k]) <= 1e-12) d[k] = 0.0;  // also turns -0 into 0
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(d[k]) - 1.0) <= 1e-9) return std::string(1, "xyz"[k]);
  char text[96];
  std::snprintf(text, sizeof text, "[%.4g, %.4g, %.4g]", d.x(), d.y(), d.z());
  return text;
}

/// `p` with the coordinates that are round-off against `scale` [mm] written as 0.
std::string point_text(Vec3d p, double scale) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(p[k]) <= 1e-9 * scale) p[k] = 0.0;  // also turns -0 into 0
  char text[96];
  std::snprintf(text, sizeof text, "[%.4g, %.4g, %.4g]", p.x(), p.y(), p.z());
  return text;
}

/// Union-find over the mesh's nodes.
struct Pieces {
  std::vector<int> parent;
  explicit Pieces(int n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int root(int v) {
    while (parent[static_cast<std::size_t>(v)] != v)
      v = parent[static_cast<std::size_t>(v)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
    return v;
  }
  void join(int a, int b) { parent[static_cast<std::size_t>(root(a))] = root(b); }
};

/// What one piece's holds leave free, in scaled coordinates s = (a, w L).
struct PieceRows {
  Mat6d gram = Mat6d::Zero();
  void add(const Vec6d& row) { gram += row * row.transpose(); }
};

/// Zeroes the parts of `s` that are round-off against its largest: the motion's names then test
/// exact zeros.
Vec6d cleaned(Vec6d s) {
  const double largest = s.cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i)
    if (std::abs(s[i]) <= 1e-9 * largest) s[i] = 0.0;
  return s;
}

}  // namespace

std::string RigidMotion::describe() const {
  const double w = rotation.norm();
  if (w == 0.0) return "translation along " + direction_text(translation.normalized());
  const Vec3d axis = rotation / w;
  const Vec3d point = centre + rotation.cross(translation) / (w * w);
  const double slide = translation.dot(axis);
  const bool screw = std::abs(slide) > 1e-9 * translation.norm() && slide != 0.0;
  const double scale = translation.norm() / w + centre.norm();
  return std::string(screw ? "screw motion" : "rotation") + " about " + direction_text(axis) +
         " through " + point_text(point, scale);
}

std::string piece_text(const FreePiece& piece, const Mesh& mesh) {
  char text[200];
  std::snprintf(text, sizeof text, "%s of %d %s (centred near [%.4g, %.4g, %.4g])",
                piece.n_pieces > 1 ? "a piece of the mesh" : "the body", piece.n_elements,
                mesh.is_shell() ? "triangles" : "tetrahedra", piece.centre.x(), piece.centre.y(),
                piece.centre.z());
  return text;
}

std::string free_motion_text(const std::string& motion, const Mesh& mesh, int node) {
  const Vec3d& x = mesh.nodes[static_cast<std::size_t>(node)];
  char where[160];
  std::snprintf(where, sizeof where, " (node %d at [%.6g, %.6g, %.6g] moves so)", node, x.x(),
                x.y(), x.z());
  return "can still move as a rigid body by " + motion + where;
}

int farthest_moved(const RigidMotion& motion, const Mesh& mesh, const std::vector<int>& nodes) {
  int carrier = nodes.empty() ? -1 : nodes.front();
  double farthest = -1.0;
  for (int v : nodes) {
    const double moved = motion.at(mesh.nodes[static_cast<std::size_t>(v)]).norm();
    if (moved > farthest * (1.0 + 1e-12)) {  // the first of nodes moved alike
      farthest = moved;
      carrier = v;
    }
  }
  return carrier;
}

std::vector<FreePiece> free_rigid_motions(const Mesh& mesh,
                                          const std::vector<ConstrainedComponent>& constraints,
                                          const std::vector<RigidHold>& holds) {
  const int n_nodes = mesh.n_nodes();
  Pieces pieces(n_nodes);
  std::vector<char> in_element(static_cast<std::size_t>(n_nodes), 0);
  std::vector<int> first_node;  // per element
  const auto add_element = [&](auto nodes) {
    for (int v : nodes) {
      pieces.join(v, nodes[0]);
      in_element[static_cast<std::size_t>(v)] = 1;
    }
    first_node.push_back(nodes[0]);
  };
  if (mesh.is_shell()) {
    for (const auto& t : mesh.triangles) add_element(t);
  } else {
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      add_element(mesh.tets[t]);
      if (!mesh.tet_edge_nodes.empty())
        for (int v : mesh.tet_edge_nodes[t]) {
          pieces.join(v, mesh.tets[t][0]);
          in_element[static_cast<std::size_t>(v)] = 1;
        }
    }
  }
  for (const RigidHold& hold : holds)
    for (int v : hold.nodes) pieces.join(v, hold.nodes.front());

  // Each piece's centre and size: its nodes' mean, and their largest distance from it.
  std::vector<int> count(static_cast<std::size_t>(n_nodes), 0), elements(count);
  std::vector<Vec3d> centre(static_cast<std::size_t>(n_nodes), Vec3d::Zero());
  std::vector<double> size(static_cast<std::size_t>(n_nodes), 0.0);
  for (int v = 0; v < n_nodes; ++v)
    if (in_element[static_cast<std::size_t>(v)]) {
      const auto r = static_cast<std::size_t>(pieces.root(v));
      centre[r] += mesh.nodes[static_cast<std::size_t>(v)];
      ++count[r];
    }
  for (int v : first_node) ++elements[static_cast<std::size_t>(pieces.root(v))];
  for (int r = 0; r < n_nodes; ++r)
    if (count[static_cast<std::size_t>(r)] > 0)
      centre[static_cast<std::size_t>(r)] /= count[static_cast<std::size_t>(r)];
  for (int v = 0; v < n_nodes; ++v)
    if (in_element[static_cast<std::size_t>(v)]) {
      const auto r = static_cast<std::size_t>(pieces.root(v));
      size[r] = std::max(size[r], (mesh.nodes[static_cast<std::size_t>(v)] - centre[r]).norm());
    }
  for (double& s : size) s = s > 0.0 ? s : 1.0;

  // Rows: a held displacement component n . u(P) = n . a + (w L) . ((P - c) x n) / L, a held
  // rotation component (w L) . n.
  std::vector<PieceRows> rows(static_cast<std::size_t>(n_nodes));
  const auto hold_row = [&](int node, const Vec3d& point, const Vec3d& n, bool rotation) {
    const auto r = static_cast<std::size_t>(pieces.root(node));
    Vec6d row;
    if (rotation)
      row << Vec3d::Zero(), n;
    else
      row << n, (point - centre[r]).cross(n) / size[r];
    rows[r].add(row);
  };
  for (const ConstrainedComponent& c : constraints)
    if (c.component < 3 && in_element[static_cast<std::size_t>(c.node)])
      hold_row(c.node, mesh.nodes[static_cast<std::size_t>(c.node)], Vec3d::Unit(c.component),
               false);
  for (const RigidHold& hold : holds)
    if (hold.direction.squaredNorm() > 0.0 && !hold.nodes.empty())
      hold_row(hold.nodes.front(), hold.point, hold.direction.normalized(), hold.rotation);

  // A shell's clamped and symmetry sides (Mesh::side_mirrors): the element sees the node across
  // the side as the image Y = P + M (X - P) of the corner X opposite it, so a rigid motion costs
  // no energy there only if M u(X) = u(Y): three rows in (a, w), M u(X) - u(Y) =
  // (M - I) a + ([Y - c]x - M [X - c]x) w.
  if (!mesh.side_mirrors.empty())
    for (const auto& tri : mesh.triangles)
      for (int i = 0; i < 3; ++i) {
        const auto found = mesh.side_mirrors.find({tri[(i + 1) % 3], tri[(i + 2) % 3]});
        if (found == mesh.side_mirrors.end()) continue;
        const auto r = static_cast<std::size_t>(pieces.root(tri[0]));
        const SideMirror& mirror = found->second;
        const Vec3d& X = mesh.nodes[static_cast<std::size_t>(tri[i])];
        const Vec3d Y = mirror.point + mirror.map * (X - mirror.point);
        Eigen::Matrix<double, 3, 6> block;
        block << mirror.map - Mat3d::Identity(),
            (cross_matrix(Y - centre[r]) - mirror.map * cross_matrix(X - centre[r])) / size[r];
        rows[r].gram += block.transpose() * block;
      }

  int n_pieces = 0;
  for (int r = 0; r < n_nodes; ++r) n_pieces += elements[static_cast<std::size_t>(r)] > 0;
  std::vector<FreePiece> free;
  for (int r = 0; r < n_nodes; ++r) {
    const auto ri = static_cast<std::size_t>(r);
    if (elements[ri] == 0 || pieces.root(r) != r) continue;
    const Eigen::SelfAdjointEigenSolver<Mat6d> eigen(rows[ri].gram);
    const double largest = std::max(eigen.eigenvalues().maxCoeff(), 0.0);
    std::vector<Vec6d> null;
    for (int i = 0; i < 6; ++i)
      if (eigen.eigenvalues()[i] <= kFree * largest) null.push_back(eigen.eigenvectors().col(i));
    if (null.empty()) continue;
    Eigen::MatrixXd N(6, static_cast<Eigen::Index>(null.size()));
    for (std::size_t j = 0; j < null.size(); ++j) N.col(static_cast<Eigen::Index>(j)) = null[j];

    // A basis that reads well: the coordinate translations, then the rotations about the
    // coordinate axes through the nearest point that leaves them free, then what is left.
    std::vector<Vec6d> chosen, orthonormal;
    const auto offer = [&](const Vec6d& s) {
      if ((s - N * (N.transpose() * s)).norm() > kInside * s.norm()) return;
      Vec6d w = s;
      for (const Vec6d& b : orthonormal) w -= b.dot(w) * b;
      if (w.norm() <= 0.5 * s.norm()) return;  // nearly a combination of those chosen
      chosen.push_back(cleaned(s));
      orthonormal.push_back(w.normalized());
    };
    for (int k = 0; k < 3; ++k) offer((Vec6d() << Vec3d::Unit(k), Vec3d::Zero()).finished());
    for (int k = 0; k < 3; ++k) {
      // s = (t, e_k) with t across e_k chosen to bring s nearest the free space.
      const Vec3d e1 = Vec3d::Unit((k + 1) % 3), e2 = Vec3d::Unit((k + 2) % 3);
      Eigen::Matrix<double, 6, 2> T;
      T << e1, e2, Vec3d::Zero(), Vec3d::Zero();
      Vec6d s0;
      s0 << Vec3d::Zero(), Vec3d::Unit(k);
      const Mat6d out = Mat6d::Identity() - N * N.transpose();
      const Eigen::Vector2d t = (out * T).colPivHouseholderQr().solve(-(out * s0));
      offer(s0 + T * t);
    }
    for (const Vec6d& n : null) offer(n);
    for (const Vec6d& n : null) {  // whatever round-off kept out above
      if (chosen.size() == null.size()) break;
      Vec6d w = n;
      for (const Vec6d& b : orthonormal) w -= b.dot(w) * b;
      if (w.norm() > 1e-6) {
        chosen.push_back(cleaned(w.normalized()));
        orthonormal.push_back(w.normalized());
      }
    }

    FreePiece piece;
    piece.n_elements = elements[ri];
    piece.n_pieces = n_pieces;
    piece.centre = centre[ri];
    piece.size = size[ri];
    for (int v = 0; v < n_nodes; ++v)
      if (in_element[static_cast<std::size_t>(v)] && pieces.root(v) == r)
        piece.members.push_back(v);
    for (const Vec6d& s : chosen) {
      RigidMotion m{s.head<3>(), s.tail<3>() / size[ri], centre[ri]};
      piece.motions.push_back(m);
      piece.nodes.push_back(farthest_moved(m, mesh, piece.members));
    }
    free.push_back(std::move(piece));
  }
  return free;
}

}  // namespace plisse
