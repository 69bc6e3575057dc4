#include "solver/shell_patch.hpp"

#include <utility>

namespace plisse {

namespace {

using shell::kPatchNodes;
using shell::outer_slot;
using shell::Slot;

/// The mirror map of the side of the triangle with corners `corners` opposite corner i, or null.
const SideMirror* mirror_of_side(const Mesh& mesh, const std::array<int, 3>& corners, int i) {
  if (mesh.side_mirrors.empty()) return nullptr;
  const auto m = mesh.side_mirrors.find({corners[(i + 1) % 3], corners[(i + 2) % 3]});
  return m == mesh.side_mirrors.end() ? nullptr : &m->second;
}

Vec3d image_of(const SideMirror& m, const Vec3d& X) { return m.point + m.map * (X - m.point); }

/// Beyond a mirrored side i, slot 6 + 2i + w is the image of the slot across one of the
/// triangle's other sides (KL3b): the image triangle's side opposite corner i + 1 + w is the
/// image of the triangle's side opposite the corner the map takes there. A reflection through a
/// plane keeps the side's corners, a half turn about the normal swaps them.
int imaged_slot(const Mesh& mesh, const SideMirror& m, const std::array<int, 3>& corners, int i,
                int w) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const Vec3d& Xj = mesh.nodes[corners[j]];
  const Vec3d& Xk = mesh.nodes[corners[k]];
  const Vec3d image_j = image_of(m, Xj);
  const bool keeps = (image_j - Xj).norm() <= (image_j - Xk).norm();
  const int corner = w == 0 ? j : k, other = w == 0 ? k : j;
  return 3 + (keeps ? corner : other);
}

}  // namespace

std::array<int, kPatchNodes> shell_patch_nodes(const Mesh& mesh, int e) {
  const auto t = static_cast<std::size_t>(e);
  const std::array<int, 3>& corners = mesh.triangles[t];
  const auto& across = mesh.triangle_neighbours[t];
  const auto& adjacent = mesh.triangle_adjacent[t];
  std::array<int, kPatchNodes> n;
  for (int i = 0; i < 3; ++i) {
    n[i] = corners[i];
    n[3 + i] = across[i] >= 0 ? across[i] : corners[i];
  }
  for (int i = 0; i < 3; ++i) {
    const SideMirror* mirror = adjacent[i] < 0 ? mirror_of_side(mesh, corners, i) : nullptr;
    for (int w = 0; w < 2; ++w) {
      const int source = corners[(i + 1 + w) % 3];
      int beyond = source;
      if (adjacent[i] >= 0) {  // the node across the neighbour's side opposite `source`
        const auto& neighbour = mesh.triangles[static_cast<std::size_t>(adjacent[i])];
        for (int s = 0; s < 3; ++s)
          if (neighbour[s] == source && mesh.triangle_neighbours[adjacent[i]][s] >= 0)
            beyond = mesh.triangle_neighbours[adjacent[i]][s];
      } else if (mirror != nullptr) {
        beyond = n[imaged_slot(mesh, *mirror, corners, i, w)];
      }
      n[outer_slot(i, w)] = beyond;
    }
  }
  return n;
}

ShellPatchSlots shell_patch_slots(const Mesh& mesh, std::span<const int, kPatchNodes> nodes) {
  ShellPatchSlots s;
  const std::array<int, 3> corners = {nodes[0], nodes[1], nodes[2]};
  // Each slot's displacement as a linear form in the slots: form[a][b] multiplies u_b.
  std::array<std::array<Mat3d, kPatchNodes>, kPatchNodes> form;
  for (int a = 0; a < kPatchNodes; ++a) {
    s.X[a] = mesh.nodes[nodes[a]];
    s.kinds[a] = Slot::node;
    for (int b = 0; b < kPatchNodes; ++b)
      form[a][b] = a == b ? Mat3d::Identity().eval() : Mat3d::Zero().eval();
  }
  // Slot a becomes the image of slot `from` under the map R of the side with corners p and q
  // about the side's midpoint, which moves with the side (KL8a): X = c + R (X_from - c) in the
  // reference, and u = R u_from + (I - R)(u_p + u_q)/2.
  const auto make_image = [&](int a, const SideMirror& m, int from, int p, int q) {
    s.kinds[a] = Slot::image;
    const Vec3d c = 0.5 * (s.X[p] + s.X[q]);
    s.X[a] = c + m.map * (s.X[from] - c);
    const Mat3d half_rest = 0.5 * (Mat3d::Identity() - m.map);
    std::array<Mat3d, kPatchNodes> image;
    for (int b = 0; b < kPatchNodes; ++b) image[b] = m.map * form[from][b];
    image[p] += half_rest;
    image[q] += half_rest;
    form[a] = image;
  };
  // Across the sides first: the slots beyond a mirrored side are images of these.
  for (int i = 0; i < 3; ++i) {
    if (nodes[3 + i] != nodes[i]) continue;
    s.kinds[3 + i] = Slot::missing;
    if (const SideMirror* m = mirror_of_side(mesh, corners, i))
      make_image(3 + i, *m, i, (i + 1) % 3, (i + 2) % 3);
  }
  for (int i = 0; i < 3; ++i) {
    for (int w = 0; w < 2; ++w) {
      const int a = outer_slot(i, w);
      const int source = (i + 1 + w) % 3;
      if (s.kinds[3 + i] == Slot::node) {
        if (nodes[a] != nodes[source]) continue;
        s.kinds[a] = Slot::missing;
        // The neighbour's side opposite `source`, directed as the neighbour runs through it.
        const int o = nodes[3 + i], j = nodes[(i + 1) % 3], k = nodes[(i + 2) % 3];
        const std::pair<int, int> key = w == 0 ? std::pair{o, k} : std::pair{j, o};
        const auto m = mesh.side_mirrors.find(key);
        if (m != mesh.side_mirrors.end()) {
          make_image(a, m->second, source, w == 0 ? 3 + i : (i + 1) % 3,
                     w == 0 ? (i + 2) % 3 : 3 + i);
        }
      } else if (s.kinds[3 + i] == Slot::image) {
        const SideMirror& m = *mirror_of_side(mesh, corners, i);
        const int from = imaged_slot(mesh, m, corners, i, w);
        if (s.kinds[from] == Slot::missing) {
          s.kinds[a] = Slot::missing;  // the image of a ghost is the ghost of the image (KL8)
        } else {
          make_image(a, m, from, (i + 1) % 3, (i + 2) % 3);
        }
      } else {
        s.kinds[a] = Slot::missing;  // beyond a free side: unused
      }
    }
  }
  for (int a = 0; a < kPatchNodes; ++a) {
    if (s.kinds[a] != Slot::image) continue;
    for (int b = 0; b < kPatchNodes; ++b)
      if (!form[a][b].isZero(0.0)) s.image_terms.push_back({a, b, form[a][b]});
  }
  return s;
}

}  // namespace plisse
