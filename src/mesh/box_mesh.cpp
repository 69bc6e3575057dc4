#include "mesh/box_mesh.hpp"

#include "core/error.hpp"
#include "mesh/boundary_tags.hpp"
#include "mesh/second_order.hpp"

namespace plisse {

void append_kuhn_tets(Mesh& mesh, const std::array<int, 3>& cells,
                      const std::function<int(int, int, int)>& node) {
  // The six axis permutations (a, b, c); odd ones give negatively oriented paths.
  static constexpr std::array<std::array<int, 3>, 6> kPermutations = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  mesh.tets.reserve(mesh.tets.size() +
                    static_cast<std::size_t>(6 * cells[0] * cells[1] * cells[2]));
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
        for (const auto& p : kPermutations) {
          std::array<int, 3> corner = {i, j, k};
          std::array<int, 4> tet{};
          tet[0] = node(i, j, k);
          for (std::size_t s = 0; s < 3; ++s) {
            ++corner[static_cast<std::size_t>(p[s])];
            tet[s + 1] = node(corner[0], corner[1], corner[2]);
          }
          mesh.tets.push_back(tet);
        }
}

Mesh make_box_mesh(const Vec3d& extent, const std::array<int, 3>& cells, int order) {
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  PLISSE_CHECK(nx >= 1 && ny >= 1 && nz >= 1, "make_box_mesh: cell counts must be >= 1");
  PLISSE_CHECK(order == 1 || order == 2, "make_box_mesh: order must be 1 or 2");
  Mesh mesh;
  auto coordinate = [](double length, int i, int n) { return i == n ? length : length * i / n; };
  auto node = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  mesh.nodes.reserve(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.nodes.emplace_back(coordinate(extent.x(), i, nx), coordinate(extent.y(), j, ny),
                                coordinate(extent.z(), k, nz));
  append_kuhn_tets(mesh, cells, node);
  orient_generated_tets(mesh, "box mesh");

  enum Side { kLeft, kRight, kFront, kBack, kBottom, kTop };
  const std::vector<std::vector<std::string>> side_tags = {
      {"left", "sym_x"}, {"right"}, {"front", "sym_y"}, {"back"}, {"bottom", "sym_z"}, {"top"}};
  tag_boundary(mesh, side_tags, [&](const BoundaryFace& f) {
    auto all = [&](int axis, double value) {
      for (int n : f.nodes)
        if (mesh.nodes[static_cast<std::size_t>(n)][axis] != value) return false;
      return true;
    };
    if (all(0, 0.0)) return static_cast<int>(kLeft);
    if (all(0, extent.x())) return static_cast<int>(kRight);
    if (all(1, 0.0)) return static_cast<int>(kFront);
    if (all(1, extent.y())) return static_cast<int>(kBack);
    if (all(2, 0.0)) return static_cast<int>(kBottom);
    if (all(2, extent.z())) return static_cast<int>(kTop);
    return -1;
  });
  if (order == 2) add_straight_edge_nodes(mesh);
  return mesh;
}

Mesh make_rectangle_surface(double length, double width, double z,
                            const std::array<int, 2>& cells) {
  const int nx = cells[0], ny = cells[1];
  PLISSE_CHECK(nx >= 1 && ny >= 1, "make_rectangle_surface: cell counts must be >= 1");
  Mesh mesh;
  auto coordinate = [](double extent, int i, int n) { return i == n ? extent : extent * i / n; };
  auto node = [&](int i, int j) { return i + (nx + 1) * j; };
  mesh.nodes.reserve(static_cast<std::size_t>((nx + 1) * (ny + 1)));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.nodes.emplace_back(coordinate(length, i, nx), coordinate(width, j, ny), z);
  mesh.triangles.reserve(static_cast<std::size_t>(2 * nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      mesh.triangles.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  std::vector<int> all(mesh.triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
  mesh.surface_tags["bottom"] = all;
  mesh.surface_tags["top"] = all;
  mesh.shell_face_side = {{"bottom", -1}, {"top", +1}};
  tag_boundary_edges(mesh, {{{"left", "sym_x"}, 0, 0.0},
                            {{"right"}, 0, length},
                            {{"front", "sym_y"}, 1, 0.0},
                            {{"back"}, 1, width}});
  return mesh;
}

}  // namespace plisse
